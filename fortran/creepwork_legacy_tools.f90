! creepwork_legacy_tools.f90 -- the legacy layer's routines around the
! solves (conventions: creepwork_legacy.f90): time accumulation of the work,
! Kalker's coefficients and flexibilities, Hertz, the messages and the check
! of the caller's kinds.

! Time accumulation for a simulation loop (paper eqs. 35 and 37), on the
! caller's arrays: adds one step of length DIST = V*dt [m] (finite, >= 0).
!   NX, NY       grid of the maps
!   DIST         V*dt of the step [m]
!   WMAC, WMIC   the step's macro and paper micro work per unit distance [J/m]
!   WPAP, WCON   the step's paper and energy-consistent maps [J/m] (NX, NY)
!                (outputs of CWSOLM/CWSOLL)
! Running totals (in/out; start them at zero):
!   DSUM         rolled distance [m]
!   WMSUM        macro work [J] (eq. 35);  WPSUM  paper micro work [J] (eq. 37)
!   WPACC, WCACC accumulated paper and energy-consistent maps [J] (NX, NY);
!                WCACC sums to WMSUM
! Output:
!   CKRUN        K over the run, WMSUM/WPSUM (eq. 39; 0 while WPSUM = 0)
!   IERR         0, CW_ERR_GRID_OUT_OF_RANGE (NX, NY), CW_ERR_INVALID_INPUT
!                (DIST, or a subnormal input) or CW_ERR_NUMERIC (a total
!                would overflow): nothing is changed then.
! The arithmetic is that of cw_accumulator_add, so the totals equal the C
! accumulator's to the last bit (a subnormal sum, which that flushes, is 0).
subroutine CWACCU(NX, NY, DIST, WMAC, WMIC, WPAP, WCON, DSUM, WMSUM, WPSUM, WPACC, WCACC, &
                  CKRUN, IERR)
   use, intrinsic :: iso_c_binding, only: c_double, c_int
   use, intrinsic :: ieee_exceptions, only: ieee_status_type, ieee_get_status, ieee_set_status, &
                                            ieee_set_halting_mode, ieee_usual, ieee_underflow
   implicit none
   integer(c_int), intent(in) :: NX, NY
   real(c_double), intent(in) :: DIST, WMAC, WMIC
   real(c_double), intent(in), dimension(NX, NY) :: WPAP, WCON
   real(c_double), intent(inout) :: DSUM, WMSUM, WPSUM
   real(c_double), intent(inout), dimension(NX, NY) :: WPACC, WCACC
   real(c_double), intent(inout) :: CKRUN
   integer(c_int), intent(out) :: IERR
   interface
      subroutine cwaccu_body(nx, ny, dist, wmac, wmic, wpap, wcon, dsum, wmsum, wpsum, wpacc, &
                             wcacc, ckrun, ierr)
         import :: c_double, c_int
         integer(c_int), intent(in) :: nx, ny
         real(c_double), intent(in) :: dist, wmac, wmic
         real(c_double), intent(in), dimension(nx, ny) :: wpap, wcon
         real(c_double), intent(inout) :: dsum, wmsum, wpsum
         real(c_double), intent(inout), dimension(nx, ny) :: wpacc, wcacc
         real(c_double), intent(inout) :: ckrun
         integer(c_int), intent(out) :: ierr
      end subroutine cwaccu_body
   end interface
   type(ieee_status_type) :: caller
   ! Halting off while the sums are formed and checked; the caller's halting
   ! modes and flags back afterwards, so an overflow found here is a status.
   call ieee_get_status(caller)
   call ieee_set_halting_mode(ieee_usual, .false.)
   call ieee_set_halting_mode(ieee_underflow, .false.)
   call cwaccu_body(NX, NY, DIST, WMAC, WMIC, WPAP, WCON, DSUM, WMSUM, WPSUM, WPACC, WCACC, &
                    CKRUN, IERR)
   call ieee_set_status(caller)
end subroutine CWACCU

! CWACCU's arithmetic, run with halting off (not for callers).
subroutine cwaccu_body(NX, NY, DIST, WMAC, WMIC, WPAP, WCON, DSUM, WMSUM, WPSUM, WPACC, WCACC, &
                       CKRUN, IERR)
   use, intrinsic :: iso_c_binding, only: c_double, c_int
   use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
   use creepwork, only: CW_OK, CW_ERR_INVALID_INPUT, CW_ERR_NUMERIC
   use creepwork_legacy_support, only: subnormal, flushed, check_normal, check_array, check_cells, &
                                       remember, remember_error, real_text
   implicit none
   integer(c_int), intent(in) :: NX, NY
   real(c_double), intent(in) :: DIST, WMAC, WMIC
   real(c_double), intent(in), dimension(NX, NY) :: WPAP, WCON
   real(c_double), intent(inout) :: DSUM, WMSUM, WPSUM
   real(c_double), intent(inout), dimension(NX, NY) :: WPACC, WCACC
   real(c_double), intent(inout) :: CKRUN
   integer(c_int), intent(out) :: IERR
   real(c_double) :: d, wm, wp, k
   integer :: i, j
   call check_cells(NX, 'NX', IERR)
   if (IERR == CW_OK) call check_cells(NY, 'NY', IERR)
   if (IERR /= CW_OK) return
   ! Subnormal inputs are read by nothing (they would trip a denormal trap).
   call check_normal([DIST, WMAC, WMIC, DSUM, WMSUM, WPSUM], 'DIST WMAC WMIC DSUM WMSUM WPSUM', IERR)
   call check_array(any(subnormal(WPAP)), 'WPAP', IERR)
   call check_array(any(subnormal(WCON)), 'WCON', IERR)
   call check_array(any(subnormal(WPACC)), 'WPACC', IERR)
   call check_array(any(subnormal(WCACC)), 'WCACC', IERR)
   if (IERR /= CW_OK) return
   if (.not. (ieee_is_finite(DIST) .and. DIST >= 0.0_c_double)) then
      call remember_error(CW_ERR_INVALID_INPUT, 'DIST = '//trim(real_text(DIST))// &
                          ' is invalid: must be finite and >= 0', IERR)
      return
   end if
   d = flushed(DSUM + DIST)
   wm = flushed(WMSUM + flushed(WMAC*DIST))
   wp = flushed(WPSUM + flushed(WMIC*DIST))
   k = 0.0_c_double
   if (wp /= 0.0_c_double) k = flushed(wm/wp)
   if (.not. (ieee_is_finite(d) .and. ieee_is_finite(wm) .and. ieee_is_finite(wp) .and. &
              ieee_is_finite(k))) then
      call remember_error(CW_ERR_NUMERIC, 'a running total (DSUM, WMSUM, WPSUM, CKRUN) would '// &
                          'overflow', IERR)
      return
   end if
   do j = 1, NY
      do i = 1, NX
         if (.not. (ieee_is_finite(WPACC(i, j) + DIST*WPAP(i, j)) .and. &
                    ieee_is_finite(WCACC(i, j) + DIST*WCON(i, j)))) then
            call remember_error(CW_ERR_NUMERIC, 'an accumulated map (WPACC, WCACC) would '// &
                                'overflow', IERR)
            return
         end if
      end do
   end do
   do j = 1, NY
      do i = 1, NX
         WPACC(i, j) = flushed(WPACC(i, j) + flushed(DIST*WPAP(i, j)))
         WCACC(i, j) = flushed(WCACC(i, j) + flushed(DIST*WCON(i, j)))
      end do
   end do
   DSUM = d
   WMSUM = wm
   WPSUM = wp
   CKRUN = k
   IERR = CW_OK
   call remember('')
end subroutine cwaccu_body

! Kalker's creepage and spin coefficients (Kalker 1990, Table E.3;
! asymptotes below min(a/b, b/a) = 0.1), as cw_kalker_coefficients:
!   AOB       semi-axis ratio a/b [-], 1e-3 .. 1e3
!   PNU       Poisson's ratio [-], 0 .. 0.5
!   C11, C22, C23, C33  (out) the coefficients [-]
!   IERR      0 or CW_ERR_INVALID_INPUT (outputs unchanged)
subroutine CWKALK(AOB, PNU, C11, C22, C23, C33, IERR)
   use, intrinsic :: iso_c_binding, only: c_double, c_int
   use creepwork, only: cw_kalker_coefficients, CW_OK
   use creepwork_legacy_support, only: check_normal, remember
   implicit none
   real(c_double), intent(in) :: AOB, PNU
   real(c_double), intent(inout) :: C11, C22, C23, C33
   integer(c_int), intent(out) :: IERR
   real(c_double) :: c(4)
   character(len=:), allocatable :: message
   integer :: stat
   call check_normal([AOB, PNU], 'AOB PNU', IERR)
   if (IERR /= CW_OK) return
   c = 0.0_c_double
   call cw_kalker_coefficients(AOB, PNU, c, stat=stat, errmsg=message)
   IERR = int(stat, c_int)
   call remember(message)
   if (IERR /= CW_OK) return
   C11 = c(1)
   C22 = c(2)
   C23 = c(3)
   C33 = c(4)
end subroutine CWKALK

! Kalker's flexibilities of the simplified theory (Kalker 1982), as
! cw_kalker_flexibilities: L1 = 8A/(3 C11 G), L2 = 8A/(3 C22 G),
! L3 = pi A sqrt(A/B)/(4 C23 G).
!   A, B          semi-axes [m];  G  combined shear modulus [Pa];  PNU  [-]
!   FL1, FL2, FL3 (out) flexibilities [m/Pa]: for CWSOLL, or for CWFSIM's
!                 UX = pi A^2 B XI/(2 FMU FN FL1), UY = pi A^2 B ETA/(2 FMU FN FL2),
!                 FX = pi A^2 B^2 PHI/(2 FMU FN FL3), FY = pi A^3 B PHI/(2 FMU FN FL3)
!   IERR          0 or CW_ERR_INVALID_INPUT (outputs unchanged)
subroutine CWFLEX(A, B, G, PNU, FL1, FL2, FL3, IERR)
   use, intrinsic :: iso_c_binding, only: c_double, c_int
   use creepwork, only: cw_kalker_flexibilities, CW_OK
   use creepwork_legacy_support, only: check_normal, remember
   implicit none
   real(c_double), intent(in) :: A, B, G, PNU
   real(c_double), intent(inout) :: FL1, FL2, FL3
   integer(c_int), intent(out) :: IERR
   real(c_double) :: L(3)
   character(len=:), allocatable :: message
   integer :: stat
   call check_normal([A, B, G, PNU], 'A B G PNU', IERR)
   if (IERR /= CW_OK) return
   L = 0.0_c_double
   call cw_kalker_flexibilities(A, B, G, PNU, L, stat=stat, errmsg=message)
   IERR = int(stat, c_int)
   call remember(message)
   if (IERR /= CW_OK) return
   FL1 = L(1)
   FL2 = L(2)
   FL3 = L(3)
end subroutine CWFLEX

! Hertz contact of elastically similar bodies, as cw_hertz_solve:
!   GA, GB    gap coefficients [1/m]: the undeformed gap is GA x^2 + GB y^2,
!             so GA = (1/R1x + 1/R2x)/2 -- HALF the relative curvature
!             along x (the rolling direction), GB the same across
!   FN        normal force [N];  ESTAR  contact modulus E* [Pa]
!             (G/(1 - PNU) for identical materials)
!   A, B      (out) semi-axes along x and y [m]
!   P0        (out) peak pressure 3 FN/(2 pi A B) [Pa];  APPR  approach [m]
!   IERR      0, CW_ERR_INVALID_INPUT or CW_ERR_NUMERIC (outputs unchanged)
subroutine CWHERT(GA, GB, FN, ESTAR, A, B, P0, APPR, IERR)
   use, intrinsic :: iso_c_binding, only: c_double, c_int
   use creepwork, only: cw_hertz_solve, CW_OK
   use creepwork_legacy_support, only: check_normal, remember
   implicit none
   real(c_double), intent(in) :: GA, GB, FN, ESTAR
   real(c_double), intent(inout) :: A, B, P0, APPR
   integer(c_int), intent(out) :: IERR
   real(c_double) :: h(4)
   character(len=:), allocatable :: message
   integer :: stat
   call check_normal([GA, GB, FN, ESTAR], 'GA GB FN ESTAR', IERR)
   if (IERR /= CW_OK) return
   h = 0.0_c_double
   call cw_hertz_solve(GA, GB, FN, ESTAR, h, stat=stat, errmsg=message)
   IERR = int(stat, c_int)
   call remember(message)
   if (IERR /= CW_OK) return
   A = h(1)
   B = h(2)
   P0 = h(3)
   APPR = h(4)
end subroutine CWHERT

! The message of a status: MSG (CHARACTER*(*), any length; 80 holds every
! message) receives cw_status_string(IERR), blank-padded or cut. It says
! what kind of error IERR is; CWLAST says which input caused it.
subroutine CWERRM(IERR, MSG)
   use, intrinsic :: iso_c_binding, only: c_int
   use creepwork_capi, only: capi_status_string
   use creepwork_handle, only: c_text
   implicit none
   integer(c_int), intent(in) :: IERR
   character(len=*), intent(out) :: MSG
   character(len=:), allocatable :: text
   call c_text(capi_status_string(IERR), text)
   MSG = text
end subroutine CWERRM

! The detailed message of the calling thread's last legacy call ('' after a
! success), naming the offending input, e.g. after CWKALK with PNU = 0.6:
!   an input value is invalid (NaN, Inf, out of range): nu = 0.600000
!   must lie in [0, 0.5]
! (the library's names: nu for PNU, a for A, normal_force for FN ...).
! MSG (CHARACTER*(*), any length; 200 holds nearly every message) receives
! it blank-padded, or cut to LEN(MSG). Each thread has its own last message;
! CWERRM and CWLAST leave it unchanged.
subroutine CWLAST(MSG)
   use, intrinsic :: iso_c_binding, only: c_size_t
   use creepwork_legacy_support, only: cwl_copy_message
   implicit none
   character(len=*), intent(out) :: MSG
   integer :: n
   n = int(cwl_copy_message(MSG, len(MSG, kind=c_size_t)))
   if (n < len(MSG)) MSG(n + 1:) = ' '
end subroutine CWLAST

! Checks that the caller's types are the library's. Call it once with
!   DOUBLE PRECISION R(2), INTEGER N(2), INTEGER IERR
!   R(1) = 1, R(2) = 2, N(1) = 1, N(2) = 2, IERR = -1
! declared exactly as the variables passed to the other routines. IERR = 0:
! REAL*8 and INTEGER*4 as expected. Anything else (CW_ERR_INVALID_INPUT, or
! a garbage IERR when the caller's INTEGER is 8 bytes and only 4 were
! written): the other routines would get garbage. It reads only the first 8
! bytes of R and of N, which exist whatever the caller's kinds.
subroutine CWTYPE(R, N, IERR)
   use, intrinsic :: iso_c_binding, only: c_double, c_int, c_int64_t
   use creepwork, only: CW_OK, CW_ERR_INVALID_INPUT
   use creepwork_legacy_support, only: remember, remember_error
   implicit none
   real(c_double), intent(in) :: R(2)
   integer(c_int), intent(in) :: N(2)
   integer(c_int), intent(out) :: IERR
   integer(c_int64_t) :: bits
   ! Two REAL*4 (1.0, 2.0) read as one REAL*8 are 2.0000004731118679; a
   ! REAL*16 1.0 has zero low bytes; INTEGER*8 (1, 2) reads as (1, 0).
   ! Compared as bits: garbage may be a NaN, and comparing a NaN traps.
   bits = transfer(R(1), bits)
   if (bits /= transfer(1.0_c_double, bits)) then
      call remember_error(CW_ERR_INVALID_INPUT, 'R(1) = 1 does not read as the DOUBLE PRECISION '// &
                          '1: the caller''s reals are not REAL*8 (a REAL, or -fdefault-real-8?)', IERR)
   else if (N(1) /= 1_c_int .or. N(2) /= 2_c_int) then
      call remember_error(CW_ERR_INVALID_INPUT, 'N(1), N(2) = 1, 2 do not read as INTEGER*4: '// &
                          'the caller''s integers are not 4 bytes (-fdefault-integer-8?)', IERR)
   else
      IERR = CW_OK
      call remember('')
   end if
end subroutine CWTYPE

! The library's plausibility checks of one contact as CWSOLM takes it
! (cw_params_check, the rules every door prints): NWARN receives how many
! rules its inputs break, MSG the K-th finding's message (1 <= K <= NWARN;
! blank otherwise), e.g. "a = 7.2 m is implausible for a wheel-rail
! contact: semi-axes are 1-20 mm (were millimetres typed as metres?)". The
! arguments are given explicitly, so the placeholder rule of cw_params_init
! (a, b, N left at their defaults) does not apply. IERR = 2 for an input no
! contact has (a subnormal or huge value, as CWSOLM); the checks themselves
! never fail.
subroutine CWCHEK(A, B, FN, FMU, G, PNU, XI, ETA, PHI, K, MSG, NWARN, IERR)
   use, intrinsic :: iso_c_binding, only: c_double, c_int
   use creepwork, only: cw_grid, cw_check, cw_grid_init, cw_params_check, &
                        CW_CHECK_DEFAULT_GEOMETRY, CW_OK
   use creepwork_handle, only: buffer_text
   use creepwork_legacy_support, only: check_normal, material_params, remember
   implicit none
   real(c_double), intent(in) :: A, B, FN, FMU, G, PNU, XI, ETA, PHI
   integer(c_int), intent(in) :: K
   character(len=*), intent(out) :: MSG
   integer(c_int), intent(out) :: NWARN, IERR
   type(cw_grid) :: grid
   type(cw_check), allocatable :: checks(:)
   logical, allocatable :: shown(:)
   ! A subroutine's deferred-length result, not a function's: gfortran keeps
   ! a function result's length in static data (tests/fortran, static data).
   character(len=:), allocatable :: text
   integer :: i, n
   MSG = ' '
   NWARN = 0
   call check_normal([A, B, FN, FMU, G, PNU, XI, ETA, PHI], 'A B FN FMU G PNU XI ETA PHI', IERR)
   if (IERR /= CW_OK) return
   call cw_grid_init(grid)
   call cw_params_check(grid, [material_params(A, B, FN, FMU, G, PNU, XI, ETA, PHI)], checks)
   shown = checks%rule /= CW_CHECK_DEFAULT_GEOMETRY
   NWARN = int(count(shown), c_int)
   n = 0
   do i = 1, size(checks)
      if (.not. shown(i)) cycle
      n = n + 1
      if (n == K) then
         call buffer_text(checks(i)%message, text)
         MSG = text
      end if
   end do
   call remember('')
end subroutine CWCHEK
