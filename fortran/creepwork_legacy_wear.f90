! creepwork_legacy_wear.f90 -- the legacy layer's wear routines
! (doc/theory/wear.md; conventions: creepwork_legacy.f90): the wear of one
! contact, its accumulation on a profile grid and the profile update.

! Wear of one contact (doc/theory/wear.md), flexibilities from the material as in
! CWSOLM, USFD or Archard's law with the KTH map on the energy-consistent
! work map, with the library's default coefficients (Braghin et al. 2006 for
! R8T/900A; Jendel 2002; steel 7800 kg/m^3). Other coefficients, the
! paper's map or the model's micro-slip: module creepwork (cw_wear_type).
! A pass is one axle passage (rail) or one wheel revolution (wheel).
!   A, B, FN, FMU, G, PNU, XI, ETA, PHI, NX, NY   as CWSOLM
!   LAW       0 USFD (CW_WEAR_USFD), 1 Archard/KTH (CW_WEAR_ARCHARD_KTH)
!   V         rolling speed [m/s]: Archard's sliding velocity (> 0 there);
!             >= 0 and unused for USFD
!   YS, DYS   (out) strip centres and widths [m]                (NY)
!   DEPTH     (out) wear depth per pass of each strip [m]       (NY)
!   WMASS     (out) mass worn per rolled distance [kg/m] (x 2 pi R: per
!             wheel revolution; per metre of rail per axle passage)
!   IERR      0 or a CW_* status (outputs unchanged)
! Each call makes and frees its own solver, like CWSOLM.
subroutine CWWEAR(A, B, FN, FMU, G, PNU, XI, ETA, PHI, NX, NY, LAW, V, YS, DYS, DEPTH, WMASS, &
                  IERR)
   use, intrinsic :: iso_c_binding, only: c_double, c_int
   use creepwork, only: cw_params, cw_solver_type, cw_wear_type, cw_wear_params, &
                        cw_wear_params_init, cw_wear_result, CW_SOLVE_FULL, CW_OK
   use creepwork_legacy_support, only: check_normal, check_cells, material_params, remember
   implicit none
   real(c_double), intent(in) :: A, B, FN, FMU, G, PNU, XI, ETA, PHI, V
   integer(c_int), intent(in) :: NX, NY, LAW
   real(c_double), intent(inout), dimension(NY) :: YS, DYS, DEPTH
   real(c_double), intent(inout) :: WMASS
   integer(c_int), intent(out) :: IERR
   type(cw_params) :: p
   type(cw_solver_type) :: solver
   type(cw_wear_type) :: wear
   type(cw_wear_params) :: wp
   type(cw_wear_result) :: r
   real(c_double), allocatable :: y(:), dy(:), d(:)
   character(len=:), allocatable :: message
   integer :: stat
   call check_cells(NX, 'NX', IERR)
   if (IERR == CW_OK) call check_cells(NY, 'NY', IERR)
   if (IERR == CW_OK) call check_normal([A, B, FN, FMU, G, PNU, XI, ETA, PHI, V], &
                                        'A B FN FMU G PNU XI ETA PHI V', IERR)
   if (IERR /= CW_OK) return
   allocate (y(NY), dy(NY), d(NY))
   p = material_params(A, B, FN, FMU, G, PNU, XI, ETA, PHI)
   call cw_wear_params_init(wp)
   wp%law = LAW
   wp%rolling_speed = V
   call solver%create(nx=NX, ny=NY, stat=stat, errmsg=message)
   if (stat == CW_OK) call solver%solve(p, CW_SOLVE_FULL, stat=stat, errmsg=message)
   if (stat == CW_OK) call wear%create(solver, stat=stat, errmsg=message)
   if (stat == CW_OK) call wear%compute(solver, wp, r, stat=stat, errmsg=message)
   if (stat == CW_OK) call wear%get_strips(y=y, width=dy, depth=d, stat=stat, errmsg=message)
   if (stat == CW_OK) then
      YS = y
      DYS = dy
      DEPTH = d
      WMASS = r%mass_per_distance
   end if
   IERR = int(stat, c_int)
   call remember(message)
   call wear%destroy()
   call solver%destroy()
end subroutine CWWEAR

! Adds PASSES passes of a lateral wear profile (strips YS, DYS, DEPTH, as
! CWWEAR gives them) to the wear depths PDN, PDH of a profile grid S,
! placed as cw_wear_profile_add_strips: strip j covers
!   S0 + IORI (YS(j) -+ DYS(j)/2) cos(GAMMA)
! and its worn cross-section DEPTH(j) DYS(j) is spread uniformly over it.
!   NS        number of grid nodes (2 ..)
!   S         nodes [m], strictly increasing; node k owns the cell between
!             the midpoints to its neighbours                      (NS)
!   NY        number of strips (1 .. 1000)
!   YS, DYS, DEPTH  strip centres [m], widths [m] (> 0), depth per pass
!             [m] (>= 0)                                            (NY)
!   S0        profile coordinate of the patch centre [m]
!   IORI      +1: S grows with the contact's y; -1: S falls
!   GAMMA     contact angle between the contact plane and the S axis [rad],
!             |GAMMA| <= 85 degrees (0: S runs along the surface)
!   PASSES    axle passages (rail) or wheel revolutions (wheel) [-], >= 0
! Running totals (in/out; start them at zero):
!   PDN       wear depth normal to the surface [m]                 (NS)
!   PDH       wear depth along the profile's height axis (vertical on a
!             rail, radial on a wheel), PDN/cos(GAMMA) per pass [m] (NS)
!   IERR      0, CW_ERR_INVALID_INPUT (an input, or a subnormal one) or
!             CW_ERR_NUMERIC (a depth would overflow): nothing changes then.
! The running totals are plain double sums, so splitting the same passes
! between calls changes them by rounding only (about 1e-16 relative per
! call); module creepwork's cw_wear_profile_type keeps exact sums.
subroutine CWWPRF(NS, S, NY, YS, DYS, DEPTH, S0, IORI, GAMMA, PASSES, PDN, PDH, IERR)
   use, intrinsic :: iso_c_binding, only: c_double, c_int
   use, intrinsic :: ieee_exceptions, only: ieee_status_type, ieee_get_status, ieee_set_status, &
                                            ieee_set_halting_mode, ieee_usual, ieee_underflow
   implicit none
   integer(c_int), intent(in) :: NS, NY, IORI
   real(c_double), intent(in) :: S(NS), YS(NY), DYS(NY), DEPTH(NY), S0, GAMMA, PASSES
   real(c_double), intent(inout) :: PDN(NS), PDH(NS)
   integer(c_int), intent(out) :: IERR
   interface
      subroutine cwwprf_body(ns, s, ny, ys, dys, depth, s0, iori, gamma, passes, pdn, pdh, ierr)
         import :: c_double, c_int
         integer(c_int), intent(in) :: ns, ny, iori
         real(c_double), intent(in) :: s(ns), ys(ny), dys(ny), depth(ny), s0, gamma, passes
         real(c_double), intent(inout) :: pdn(ns), pdh(ns)
         integer(c_int), intent(out) :: ierr
      end subroutine cwwprf_body
   end interface
   type(ieee_status_type) :: caller
   ! As CWACCU: halting off while the sums are formed, the caller's modes
   ! and flags back afterwards.
   call ieee_get_status(caller)
   call ieee_set_halting_mode(ieee_usual, .false.)
   call ieee_set_halting_mode(ieee_underflow, .false.)
   call cwwprf_body(NS, S, NY, YS, DYS, DEPTH, S0, IORI, GAMMA, PASSES, PDN, PDH, IERR)
   call ieee_set_status(caller)
end subroutine CWWPRF

! CWWPRF's work, run with halting off (not for callers).
subroutine cwwprf_body(NS, S, NY, YS, DYS, DEPTH, S0, IORI, GAMMA, PASSES, PDN, PDH, IERR)
   use, intrinsic :: iso_c_binding, only: c_double, c_int
   use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
   use creepwork, only: cw_wear_profile_type, CW_OK, CW_ERR_NUMERIC, CW_WEAR_DEPTH_NORMAL, &
                        CW_WEAR_DEPTH_HEIGHT, CW_ERR_INVALID_INPUT, CW_MAX_GRID_CELLS, &
                        CW_WEAR_MAX_PROFILE_NODES
   use creepwork_legacy_support, only: subnormal, flushed, check_normal, check_array, check_range, &
                                       remember, remember_error
   implicit none
   integer(c_int), intent(in) :: NS, NY, IORI
   real(c_double), intent(in) :: S(NS), YS(NY), DYS(NY), DEPTH(NY), S0, GAMMA, PASSES
   real(c_double), intent(inout) :: PDN(NS), PDH(NS)
   integer(c_int), intent(out) :: IERR
   type(cw_wear_profile_type) :: profile
   real(c_double), allocatable :: dn(:), dh(:)
   character(len=:), allocatable :: message
   integer :: stat
   call check_range(NS, 'NS', 2, int(CW_WEAR_MAX_PROFILE_NODES), CW_ERR_INVALID_INPUT, IERR)
   if (IERR == CW_OK) call check_range(NY, 'NY', 1, int(CW_MAX_GRID_CELLS), CW_ERR_INVALID_INPUT, IERR)
   if (IERR /= CW_OK) return
   call check_normal([S0, GAMMA, PASSES], 'S0 GAMMA PASSES', IERR)
   call check_array(any(subnormal(S)), 'S', IERR)
   call check_array(any(subnormal(YS)), 'YS', IERR)
   call check_array(any(subnormal(DYS)), 'DYS', IERR)
   call check_array(any(subnormal(DEPTH)), 'DEPTH', IERR)
   call check_array(any(subnormal(PDN)), 'PDN', IERR)
   call check_array(any(subnormal(PDH)), 'PDH', IERR)
   if (IERR /= CW_OK) return
   if (.not. (all(ieee_is_finite(PDN)) .and. all(ieee_is_finite(PDH)))) then
      call remember_error(CW_ERR_INVALID_INPUT, 'PDN or PDH holds a value that is not finite', IERR)
      return
   end if
   allocate (dn(NS), dh(NS))
   call profile%create(S, stat=stat, errmsg=message)
   if (stat == CW_OK) call profile%add_strips(YS, DYS, DEPTH, S0, int(IORI), GAMMA, PASSES, &
                                              stat=stat, errmsg=message)
   if (stat == CW_OK) call profile%get_depth(CW_WEAR_DEPTH_NORMAL, dn, stat=stat, errmsg=message)
   if (stat == CW_OK) call profile%get_depth(CW_WEAR_DEPTH_HEIGHT, dh, stat=stat, errmsg=message)
   call profile%destroy()
   IERR = int(stat, c_int)
   call remember(message)
   if (IERR /= CW_OK) return
   if (.not. (all(ieee_is_finite(PDN + dn)) .and. all(ieee_is_finite(PDH + dh)))) then
      call remember_error(CW_ERR_NUMERIC, 'a depth of PDN or PDH would overflow', IERR)
      return
   end if
   PDN = flushed(PDN + dn)
   PDH = flushed(PDH + dh)
end subroutine cwwprf_body

! The profile update, as cw_wear_profile_update: PNEW = POLD - smoothed
! PDEP on the nodes S, the smoothing a volume-conserving Gaussian of
! standard deviation SMOOTH [m] (0: none), so that
! sum (POLD - PNEW) x cell width = sum PDEP x cell width.
!   NS          number of nodes (2 ..)
!   S           nodes [m], strictly increasing                     (NS)
!   POLD        profile heights that wear reduces (rail head height, wheel
!               radius) [m]                                        (NS)
!   PDEP        wear depth along the same axis [m] (PDH of CWWPRF)  (NS)
!   SMOOTH      smoothing length [m], 0 .. 1e6
!   PNEW        (out) the new profile [m]                          (NS)
!   IERR        0, CW_ERR_INVALID_INPUT or CW_ERR_NUMERIC (PNEW unchanged)
subroutine CWWUPD(NS, S, POLD, PDEP, SMOOTH, PNEW, IERR)
   use, intrinsic :: iso_c_binding, only: c_double, c_int
   use creepwork, only: cw_wear_profile_update, CW_OK, CW_ERR_INVALID_INPUT, CW_WEAR_MAX_PROFILE_NODES
   use creepwork_legacy_support, only: subnormal, check_normal, check_array, check_range, remember
   implicit none
   integer(c_int), intent(in) :: NS
   real(c_double), intent(in) :: S(NS), POLD(NS), PDEP(NS), SMOOTH
   real(c_double), intent(inout) :: PNEW(NS)
   integer(c_int), intent(out) :: IERR
   character(len=:), allocatable :: message
   integer :: stat
   call check_range(NS, 'NS', 2, int(CW_WEAR_MAX_PROFILE_NODES), CW_ERR_INVALID_INPUT, IERR)
   if (IERR /= CW_OK) return
   call check_normal([SMOOTH], 'SMOOTH', IERR)
   call check_array(any(subnormal(S)), 'S', IERR)
   call check_array(any(subnormal(POLD)), 'POLD', IERR)
   call check_array(any(subnormal(PDEP)), 'PDEP', IERR)
   if (IERR /= CW_OK) return
   call cw_wear_profile_update(S, POLD, PDEP, SMOOTH, PNEW, stat=stat, errmsg=message)
   IERR = int(stat, c_int)
   call remember(message)
end subroutine CWWUPD
