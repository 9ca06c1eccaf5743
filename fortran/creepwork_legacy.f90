! creepwork_legacy.f90 -- the FORTRAN-77-callable layer of libcreepwork_fortran.
!
! Plain external subroutines: no module, no derived type, no optional
! argument in the caller. Scalars are passed by reference, arrays have
! explicit shape, the integer error flag IERR comes last (0 = success,
! otherwise a CW_* status of creepwork.h; on error nothing is written to
! the outputs). Written in Fortran so the compiler handles name mangling:
! call them from any Fortran compiler-compatible caller built with gfortran.
!
!   CWFSIM  Kalker's original normalised FASTSIM (1982): the drop-in for
!           CALL FASTSIM(UX, UY, FX, FY, MX, MY, TOL, TX, TY)
!   CWSOLM  dimensional contact with Kalker's flexibilities from G and nu:
!           forces, moment, work totals and every per-element map
!   CWSOLL  the same with the flexibilities L1, L2, L3 given
!   CWACCU  adds one time step's work into running totals (paper eqs. 35, 37)
!
! Types: every real argument is DOUBLE PRECISION (REAL*8), every integer
! argument default INTEGER. The names follow the implicit typing rule
! (I-N integer), so IMPLICIT DOUBLE PRECISION (A-H, O-Z) callers need no
! declarations. Arrays are dimensioned exactly (NX, NY) in the caller
! (element I along x, the rolling direction, J along y), as in the C layout.
! Each CWSOLM/CWSOLL call creates and frees its own solver: they keep no
! state and may be called from several threads at once. Loops that want to
! avoid that allocation use module creepwork (cw_solver_type) instead.

! Kalker's normalised interface (Kalker 1982), argument for argument:
!   UX, UY   normalised creepages pi a^2 b xi/(2 mu N L), pi a^2 b eta/(2 mu N L)
!   FX, FY   normalised spin terms pi a^2 b^2 phi/(2 mu N L), pi a^3 b phi/(2 mu N L)
!            (so FX/FY = b/a); rigid slip (UX - Y*FX, UY + X*FY) on the unit disk
!   MX, MY   elements per strip and strips (1..1000)
!   TOL      strip-refinement tolerance: when the spin pole (-UY/FY, UX/FX)
!            lies in the contact, the strips are cut at Y = UX/FX and the two
!            strips next to the cut are bisected until their centres lie
!            within TOL of it (TOL >= 1: no bisection)
!   TX, TY   (out) total tangential force / (mu*N) with the signs of Kalker's
!            printed check values, so old callers get the numbers they
!            always got: TX is the rail's x-force (sign of UX), TY the
!            wheel's y-force (opposite sign to UY). In creepwork's
!            convention (forces on the wheel): TX = -Fx/(mu N), TY = Fy/(mu N).
!   IERR     (out) 0, or CW_ERR_INVALID_INPUT / CW_ERR_GRID_OUT_OF_RANGE /
!            CW_ERR_NUMERIC; TX, TY are then left unchanged.
! A FASTSIM caller changes CALL FASTSIM(...) into CALL CWFSIM(..., IERR).
subroutine CWFSIM(UX, UY, FX, FY, MX, MY, TOL, TX, TY, IERR)
   use, intrinsic :: iso_c_binding, only: c_double
   use creepwork, only: cw_fastsim_normalised
   implicit none
   real(c_double), intent(in) :: UX, UY, FX, FY, TOL
   integer, intent(in) :: MX, MY
   real(c_double), intent(inout) :: TX, TY
   integer, intent(out) :: IERR
   call cw_fastsim_normalised(UX, UY, FX, FY, MX, MY, TOL, TX, TY, stat=IERR)
end subroutine CWFSIM

! Shared implementation of CWSOLM and CWSOLL (not for callers).
module creepwork_legacy_support
   use, intrinsic :: iso_c_binding, only: c_double, c_int
   use creepwork
   implicit none
   private
   public :: legacy_solve

contains

   subroutine legacy_solve(params, nx, ny, fx, fy, fmz, wmac, wmic, ck, px, py, sx, sy, &
                           zmap, wpap, wcon, istate, ierr)
      type(cw_params), intent(in) :: params
      integer, intent(in) :: nx, ny
      real(c_double), intent(inout) :: fx, fy, fmz, wmac, wmic, ck
      real(c_double), intent(inout), dimension(nx, ny) :: px, py, sx, sy, zmap, wpap, wcon
      integer(c_int), intent(inout) :: istate(nx, ny)
      integer, intent(out) :: ierr
      type(cw_solver_type) :: solver
      type(cw_result) :: r
      call solver%create(nx=nx, ny=ny, stat=ierr)
      if (ierr /= CW_OK) return
      call solver%solve(params, CW_SOLVE_FULL, r, stat=ierr)
      ! After a successful full solve no field can fail; stop at the first
      ! error all the same.
      if (ierr == CW_OK) call solver%get_field(CW_FIELD_PX, px, stat=ierr)
      if (ierr == CW_OK) call solver%get_field(CW_FIELD_PY, py, stat=ierr)
      if (ierr == CW_OK) call solver%get_field(CW_FIELD_SX, sx, stat=ierr)
      if (ierr == CW_OK) call solver%get_field(CW_FIELD_SY, sy, stat=ierr)
      if (ierr == CW_OK) call solver%get_field(CW_FIELD_MZ, zmap, stat=ierr)
      if (ierr == CW_OK) call solver%get_field(CW_FIELD_WORK_PAPER, wpap, stat=ierr)
      if (ierr == CW_OK) call solver%get_field(CW_FIELD_WORK_CONSISTENT, wcon, stat=ierr)
      if (ierr == CW_OK) call solver%get_state(istate, stat=ierr)
      if (ierr == CW_OK) then
         fx = r%Fx
         fy = r%Fy
         fmz = r%Mz
         wmac = r%W_macro
         wmic = r%W_micro_paper
         ck = r%K
      end if
      call solver%destroy()
   end subroutine legacy_solve

end module creepwork_legacy_support

! Extended entry, flexibilities from the material (Kalker's C11, C22, C23):
! steady rolling of an elliptic contact on Kalker's strip grid (NY strips of
! equal width, NX elements per strip), parabolic traction bound, rolling
! towards +x (leading edge at x = +A).
!   A, B      semi-axes along x (rolling) and y [m]
!   FN        normal force N [N];  FMU  friction coefficient [-]
!   G, PNU    combined shear modulus [Pa] and Poisson's ratio [-]
!   XI, ETA   longitudinal and lateral creepage [-];  PHI  spin [1/m]
!   NX, NY    grid (1..1000)
! Outputs (forces on the wheel, opposite in sign to the creepages):
!   FX, FY    creep force [N];  FMZ  creep moment about the centre [N m]
!   WMAC      macro work -(FX XI + FY ETA + FMZ PHI) per unit rolling
!             distance [J/m] (paper eq. 34)
!   WMIC      sum of the paper's local work [J/m];  CK = WMAC/WMIC (eq. 39)
!   PX, PY    traction on the wheel [Pa]           (NX, NY)
!   SX, SY    micro-slip W/V [-], 0 in adhesion      (NX, NY)
!   ZMAP      moment contribution (x py - y px) dA [N m]  (NX, NY)
!   WPAP      paper's local work [J/m]               (NX, NY)
!   WCON      energy-consistent local work [J/m], sums to WMAC   (NX, NY)
!   ISTATE    0 exterior, 1 adhesion, 2 slip         (NX, NY)
!   IERR      0 or a CW_* status
subroutine CWSOLM(A, B, FN, FMU, G, PNU, XI, ETA, PHI, NX, NY, FX, FY, FMZ, WMAC, WMIC, CK, &
                  PX, PY, SX, SY, ZMAP, WPAP, WCON, ISTATE, IERR)
   use, intrinsic :: iso_c_binding, only: c_double, c_int
   use creepwork, only: cw_params, cw_params_init, CW_FLEX_FROM_MATERIAL
   use creepwork_legacy_support, only: legacy_solve
   implicit none
   real(c_double), intent(in) :: A, B, FN, FMU, G, PNU, XI, ETA, PHI
   integer, intent(in) :: NX, NY
   real(c_double), intent(inout) :: FX, FY, FMZ, WMAC, WMIC, CK
   real(c_double), intent(inout), dimension(NX, NY) :: PX, PY, SX, SY, ZMAP, WPAP, WCON
   integer(c_int), intent(inout) :: ISTATE(NX, NY)
   integer, intent(out) :: IERR
   type(cw_params) :: p
   call cw_params_init(p)
   p%a = A
   p%b = B
   p%normal_force = FN
   p%mu = FMU
   p%flexibility = CW_FLEX_FROM_MATERIAL
   p%G = G
   p%nu = PNU
   p%xi_x = XI
   p%xi_y = ETA
   p%phi = PHI
   call legacy_solve(p, NX, NY, FX, FY, FMZ, WMAC, WMIC, CK, PX, PY, SX, SY, ZMAP, WPAP, WCON, &
                     ISTATE, IERR)
end subroutine CWSOLM

! Extended entry with given flexibilities FL1, FL2, FL3 [m/Pa] (legacy
! codes that computed Kalker's L themselves); otherwise as CWSOLM.
subroutine CWSOLL(A, B, FN, FMU, FL1, FL2, FL3, XI, ETA, PHI, NX, NY, FX, FY, FMZ, WMAC, WMIC, &
                  CK, PX, PY, SX, SY, ZMAP, WPAP, WCON, ISTATE, IERR)
   use, intrinsic :: iso_c_binding, only: c_double, c_int
   use creepwork, only: cw_params, cw_params_init, CW_FLEX_GIVEN
   use creepwork_legacy_support, only: legacy_solve
   implicit none
   real(c_double), intent(in) :: A, B, FN, FMU, FL1, FL2, FL3, XI, ETA, PHI
   integer, intent(in) :: NX, NY
   real(c_double), intent(inout) :: FX, FY, FMZ, WMAC, WMIC, CK
   real(c_double), intent(inout), dimension(NX, NY) :: PX, PY, SX, SY, ZMAP, WPAP, WCON
   integer(c_int), intent(inout) :: ISTATE(NX, NY)
   integer, intent(out) :: IERR
   type(cw_params) :: p
   call cw_params_init(p)
   p%a = A
   p%b = B
   p%normal_force = FN
   p%mu = FMU
   p%flexibility = CW_FLEX_GIVEN
   p%L1 = FL1
   p%L2 = FL2
   p%L3 = FL3
   p%xi_x = XI
   p%xi_y = ETA
   p%phi = PHI
   call legacy_solve(p, NX, NY, FX, FY, FMZ, WMAC, WMIC, CK, PX, PY, SX, SY, ZMAP, WPAP, WCON, &
                     ISTATE, IERR)
end subroutine CWSOLL

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
!                (DIST) or CW_ERR_NUMERIC (a total would overflow): nothing
!                is changed then.
! The arithmetic is that of cw_accumulator_add, so the totals equal the C
! accumulator's to the last bit.
subroutine CWACCU(NX, NY, DIST, WMAC, WMIC, WPAP, WCON, DSUM, WMSUM, WPSUM, WPACC, WCACC, &
                  CKRUN, IERR)
   use, intrinsic :: iso_c_binding, only: c_double
   use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
   use creepwork, only: CW_OK, CW_ERR_GRID_OUT_OF_RANGE, CW_ERR_INVALID_INPUT, CW_ERR_NUMERIC, &
                        CW_MAX_GRID_CELLS
   implicit none
   integer, intent(in) :: NX, NY
   real(c_double), intent(in) :: DIST, WMAC, WMIC
   real(c_double), intent(in), dimension(NX, NY) :: WPAP, WCON
   real(c_double), intent(inout) :: DSUM, WMSUM, WPSUM
   real(c_double), intent(inout), dimension(NX, NY) :: WPACC, WCACC
   real(c_double), intent(inout) :: CKRUN
   integer, intent(out) :: IERR
   real(c_double) :: d, wm, wp, k
   integer :: i, j
   if (NX < 1 .or. NX > CW_MAX_GRID_CELLS .or. NY < 1 .or. NY > CW_MAX_GRID_CELLS) then
      IERR = CW_ERR_GRID_OUT_OF_RANGE
      return
   end if
   if (.not. (ieee_is_finite(DIST) .and. DIST >= 0.0_c_double)) then
      IERR = CW_ERR_INVALID_INPUT
      return
   end if
   d = DSUM + DIST
   wm = WMSUM + WMAC*DIST
   wp = WPSUM + WMIC*DIST
   k = 0.0_c_double
   if (wp /= 0.0_c_double) k = wm/wp
   if (.not. (ieee_is_finite(d) .and. ieee_is_finite(wm) .and. ieee_is_finite(wp) .and. &
              ieee_is_finite(k))) then
      IERR = CW_ERR_NUMERIC
      return
   end if
   do j = 1, NY
      do i = 1, NX
         if (.not. (ieee_is_finite(WPACC(i, j) + DIST*WPAP(i, j)) .and. &
                    ieee_is_finite(WCACC(i, j) + DIST*WCON(i, j)))) then
            IERR = CW_ERR_NUMERIC
            return
         end if
      end do
   end do
   do j = 1, NY
      do i = 1, NX
         WPACC(i, j) = WPACC(i, j) + DIST*WPAP(i, j)
         WCACC(i, j) = WCACC(i, j) + DIST*WCON(i, j)
      end do
   end do
   DSUM = d
   WMSUM = wm
   WPSUM = wp
   CKRUN = k
   IERR = CW_OK
end subroutine CWACCU
