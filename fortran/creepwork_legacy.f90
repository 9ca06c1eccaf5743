! creepwork_legacy.f90 -- the FORTRAN-77-callable layer of libcreepwork_fortran.
!
! Plain external subroutines: no module, no derived type, no optional
! argument in the caller. Scalars are passed by reference, arrays have
! explicit shape, the integer error flag IERR comes last (0 = success,
! otherwise a CW_* status of creepwork.h, text from CWERRM; on error nothing
! is written to the outputs). Written in Fortran so the compiler handles name
! mangling: call them from any caller built with gfortran.
!
!   CWFSIM  Kalker's original normalised FASTSIM (1982): the drop-in for
!           CALL FASTSIM(UX, UY, FX, FY, MX, MY, TOL, TX, TY)
!   CWSOLM  dimensional contact with Kalker's flexibilities from G and nu:
!           forces, moment, work totals and every per-element map
!   CWSOLL  the same with the flexibilities L1, L2, L3 given
!   CWSOLX  dimensional contact on CONTACT's uniform grid with a model
!           switch: FASTSIM or Kalker's exact theory (pressure, p_max and
!           approach of its normal problem too)
!   CWJACO  forces, moment, macro work and their 4 x 4 Jacobian (FASTSIM)
!   CWACCU  adds one time step's work into running totals (paper eqs. 35, 37)
!   CWKALK  Kalker's creepage and spin coefficients C11, C22, C23, C33
!   CWFLEX  Kalker's flexibilities L1, L2, L3 (for CWSOLL and CWFSIM)
!   CWHERT  Hertz: semi-axes, peak pressure and approach from the gap
!   CWWEAR  wear of one contact (USFD or Archard/KTH): depth per pass per strip
!   CWWPRF  adds passes of a lateral wear profile to a profile grid's depths
!   CWWUPD  profile update: new = old - (smoothed) depth
!   CWERRM  the message of an IERR value
!   CWTYPE  checks that the caller's REAL and INTEGER are the library's
!
! The installed include/creepwork/fortran/creepwork_legacy.inc declares them
! EXTERNAL with every argument listed; creepwork_legacy.fi has interface
! blocks (free form) that let the compiler check every call.
!
! Types -- the one thing Fortran 77 cannot check for you: every real
! argument is DOUBLE PRECISION (REAL*8, real(c_double)), every integer
! argument INTEGER*4 (integer(c_int)). A REAL (single precision) argument, or
! a caller compiled with -fdefault-integer-8 or -fdefault-real-8 (which makes
! DOUBLE PRECISION 16 bytes), passes garbage. Where the garbage has an
! impossible pattern -- a real input that is a subnormal number, the upper
! half of a REAL*8 read from a REAL*4 that is followed by zero bytes -- IERR
! is CW_ERR_INVALID_INPUT; otherwise the results are garbage. Run CWTYPE once
! at start-up, or include creepwork_legacy.fi. The names follow the implicit
! typing rule (I-N integer), so IMPLICIT DOUBLE PRECISION (A-H, O-Z) callers
! need no declarations except CHARACTER for CWERRM's message. Arrays are
! dimensioned exactly (NX, NY) in the caller (element I along x, the rolling
! direction, J along y), as in the C layout. Each CWSOLM/CWSOLL call creates
! and frees its own solver: they keep no state and may be called from several
! threads at once. Loops that want to avoid that allocation use module
! creepwork (cw_solver_type) instead.
!
! Floating-point traps: every routine is safe in a program built with
! -ffpe-trap=invalid,zero,overflow,denormal. The library's calls mask and
! restore the floating-point state themselves (doc/reference/guarantees.md); the
! arithmetic done here (CWACCU) runs with halting off and restores the
! caller's halting modes and flags (IEEE_GET_STATUS/IEEE_SET_STATUS), and
! reads no subnormal number: such inputs are rejected, such results are 0.

! Shared by the routines below (not for callers).
module creepwork_legacy_support
   use, intrinsic :: iso_c_binding, only: c_double, c_int, c_int64_t
   use creepwork
   implicit none
   private
   public :: legacy_solve, subnormal, any_subnormal, flushed, material_params

contains

   ! x is a subnormal number: its exponent bits are zero and it is not zero.
   ! Tested on the bits, so that reading it raises no denormal exception.
   ! No physical input is ~1e-310; the usual cause is a REAL (single
   ! precision) actual argument followed by zero bytes.
   elemental logical function subnormal(x)
      real(c_double), intent(in) :: x
      integer(c_int64_t) :: bits
      bits = transfer(x, bits)
      subnormal = ibits(bits, 52, 11) == 0 .and. ibits(bits, 0, 52) /= 0
   end function subnormal

   logical function any_subnormal(values)
      real(c_double), intent(in) :: values(:)
      any_subnormal = any(subnormal(values))
   end function any_subnormal

   ! x, or 0 if it is subnormal (a result the next call would have to read).
   elemental real(c_double) function flushed(x)
      real(c_double), intent(in) :: x
      flushed = x
      if (subnormal(x)) flushed = 0.0_c_double
   end function flushed

   ! The parameters of a dimensional legacy call with flexibilities from G
   ! and PNU (CWSOLM, CWSOLX, CWJACO, CWWEAR): every other field at its default.
   function material_params(a, b, fn, fmu, g, pnu, xi, eta, phi) result(p)
      real(c_double), intent(in) :: a, b, fn, fmu, g, pnu, xi, eta, phi
      type(cw_params) :: p
      call cw_params_init(p)
      p%a = a
      p%b = b
      p%normal_force = fn
      p%mu = fmu
      p%flexibility = CW_FLEX_FROM_MATERIAL
      p%G = g
      p%nu = pnu
      p%xi_x = xi
      p%xi_y = eta
      p%phi = phi
   end function material_params

   ! Kalker's strip grid, or with box present CONTACT's uniform grid over
   ! [-box a, box a] x [-box b, box b]; pz, pmax, appr (all or none) receive
   ! the pressure map, p_max and the approach.
   subroutine legacy_solve(params, nx, ny, fx, fy, fmz, wmac, wmic, ck, px, py, sx, sy, &
                           zmap, wpap, wcon, istate, ierr, box, pz, pmax, appr)
      type(cw_params), intent(in) :: params
      integer(c_int), intent(in) :: nx, ny
      real(c_double), intent(inout) :: fx, fy, fmz, wmac, wmic, ck
      real(c_double), intent(inout), dimension(nx, ny) :: px, py, sx, sy, zmap, wpap, wcon
      integer(c_int), intent(inout) :: istate(nx, ny)
      integer(c_int), intent(out) :: ierr
      real(c_double), intent(in), optional :: box
      real(c_double), intent(inout), optional :: pz(nx, ny), pmax, appr
      type(cw_solver_type) :: solver
      type(cw_result) :: r
      integer :: stat
      if (any_subnormal([params%a, params%b, params%normal_force, params%mu, params%G, &
                         params%nu, params%L1, params%L2, params%L3, params%xi_x, &
                         params%xi_y, params%phi])) then
         ierr = CW_ERR_INVALID_INPUT
         return
      end if
      if (present(box)) then
         if (subnormal(box)) then
            ierr = CW_ERR_INVALID_INPUT
            return
         end if
         call solver%create(nx=nx, ny=ny, kind=int(CW_GRID_UNIFORM), box_scale=box, stat=stat)
      else
         call solver%create(nx=nx, ny=ny, stat=stat)
      end if
      ierr = int(stat, c_int)
      if (ierr /= CW_OK) return
      call solver%solve(params, CW_SOLVE_FULL, r, stat=stat)
      if (stat == CW_OK .and. present(pz)) call solver%get_field(CW_FIELD_PZ, pz, stat=stat)
      ! After a successful full solve no field can fail; stop at the first
      ! error all the same.
      if (stat == CW_OK) call solver%get_field(CW_FIELD_PX, px, stat=stat)
      if (stat == CW_OK) call solver%get_field(CW_FIELD_PY, py, stat=stat)
      if (stat == CW_OK) call solver%get_field(CW_FIELD_SX, sx, stat=stat)
      if (stat == CW_OK) call solver%get_field(CW_FIELD_SY, sy, stat=stat)
      if (stat == CW_OK) call solver%get_field(CW_FIELD_MZ, zmap, stat=stat)
      if (stat == CW_OK) call solver%get_field(CW_FIELD_WORK_PAPER, wpap, stat=stat)
      if (stat == CW_OK) call solver%get_field(CW_FIELD_WORK_CONSISTENT, wcon, stat=stat)
      if (stat == CW_OK) call solver%get_state(istate, stat=stat)
      if (stat == CW_OK) then
         fx = r%Fx
         fy = r%Fy
         fmz = r%Mz
         wmac = r%W_macro
         wmic = r%W_micro_paper
         ck = r%K
         if (present(pmax)) pmax = r%p_max
         if (present(appr)) appr = r%approach
      end if
      ierr = int(stat, c_int)
      call solver%destroy()
   end subroutine legacy_solve

end module creepwork_legacy_support

! Kalker's normalised interface (Kalker 1982), argument for argument:
!   UX, UY   normalised creepages pi a^2 b xi/(2 mu N L), pi a^2 b eta/(2 mu N L)
!   FX, FY   normalised spin terms pi a^2 b^2 phi/(2 mu N L), pi a^3 b phi/(2 mu N L)
!            (so FX/FY = b/a); rigid slip (UX - Y*FX, UY + X*FY) on the unit disk.
!            With Kalker's three flexibilities (CWFLEX) put L1 in UX, L2 in UY
!            and L3 in FX, FY: that is exactly the simplified theory CWSOLM
!            solves (doc/fortran-legacy.md).
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
   use, intrinsic :: iso_c_binding, only: c_double, c_int
   use creepwork, only: cw_fastsim_normalised, CW_ERR_INVALID_INPUT
   use creepwork_legacy_support, only: any_subnormal
   implicit none
   real(c_double), intent(in) :: UX, UY, FX, FY, TOL
   integer(c_int), intent(in) :: MX, MY
   real(c_double), intent(inout) :: TX, TY
   integer(c_int), intent(out) :: IERR
   integer :: stat
   if (any_subnormal([UX, UY, FX, FY, TOL])) then
      IERR = CW_ERR_INVALID_INPUT
      return
   end if
   call cw_fastsim_normalised(UX, UY, FX, FY, int(MX), int(MY), TOL, TX, TY, stat=stat)
   IERR = int(stat, c_int)
end subroutine CWFSIM

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
   use creepwork, only: cw_params
   use creepwork_legacy_support, only: legacy_solve, material_params
   implicit none
   real(c_double), intent(in) :: A, B, FN, FMU, G, PNU, XI, ETA, PHI
   integer(c_int), intent(in) :: NX, NY
   real(c_double), intent(inout) :: FX, FY, FMZ, WMAC, WMIC, CK
   real(c_double), intent(inout), dimension(NX, NY) :: PX, PY, SX, SY, ZMAP, WPAP, WCON
   integer(c_int), intent(inout) :: ISTATE(NX, NY)
   integer(c_int), intent(out) :: IERR
   type(cw_params) :: p
   p = material_params(A, B, FN, FMU, G, PNU, XI, ETA, PHI)
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
   integer(c_int), intent(in) :: NX, NY
   real(c_double), intent(inout) :: FX, FY, FMZ, WMAC, WMIC, CK
   real(c_double), intent(inout), dimension(NX, NY) :: PX, PY, SX, SY, ZMAP, WPAP, WCON
   integer(c_int), intent(inout) :: ISTATE(NX, NY)
   integer(c_int), intent(out) :: IERR
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

! Extended entry with a model switch, on CONTACT's uniform grid (NX x NY
! equal elements over [-BOX A, BOX A] x [-BOX B, BOX B]), flexibilities or
! half-space from G and PNU, rolling towards +x:
!   MODEL     0 FASTSIM (CW_MODEL_FASTSIM: Kalker's simplified theory,
!             parabolic traction bound, CONTACT's FASTSIM grid), 1 Kalker's
!             exact half-space theory (CW_MODEL_EXACT, doc/theory/exact.md:
!             its own discrete normal problem, tolerance 1e-8, at most 50
!             Newton steps, else IERR = CW_ERR_NOT_CONVERGED), 2 the
!             calibrated model (CW_MODEL_CALIBRATED; IERR says whether this
!             build has it)
!   A ... PHI as CWSOLM
!   NX, NY    elements along x and y (1..1000; exact model 1..256)
!   BOX       box scale S in [1, 100]: CONTACT's N elements across the
!             ellipse with two guard cells are NX = NY = N + 4, BOX = (N+4)/N
! Outputs as CWSOLM, and
!   PMAX      largest element pressure [Pa]
!   APPR      normal approach [m]: exact model, of its discrete normal
!             problem; FASTSIM, Hertz's
!   PZ        normal pressure [Pa]                   (NX, NY)
!   WPAP      exact model: the frictional power density per element
!             (CONTACT's FRIC_POWER at V = 1) [J/m]
! Each call makes and frees its own solver, so the exact model starts cold
! every time (warm starts from the previous step: module creepwork).
subroutine CWSOLX(MODEL, A, B, FN, FMU, G, PNU, XI, ETA, PHI, NX, NY, BOX, FX, FY, FMZ, WMAC, &
                  WMIC, CK, PMAX, APPR, PX, PY, PZ, SX, SY, ZMAP, WPAP, WCON, ISTATE, IERR)
   use, intrinsic :: iso_c_binding, only: c_double, c_int
   use creepwork, only: cw_params
   use creepwork_legacy_support, only: legacy_solve, material_params
   implicit none
   integer(c_int), intent(in) :: MODEL
   real(c_double), intent(in) :: A, B, FN, FMU, G, PNU, XI, ETA, PHI, BOX
   integer(c_int), intent(in) :: NX, NY
   real(c_double), intent(inout) :: FX, FY, FMZ, WMAC, WMIC, CK, PMAX, APPR
   real(c_double), intent(inout), dimension(NX, NY) :: PX, PY, PZ, SX, SY, ZMAP, WPAP, WCON
   integer(c_int), intent(inout) :: ISTATE(NX, NY)
   integer(c_int), intent(out) :: IERR
   type(cw_params) :: p
   p = material_params(A, B, FN, FMU, G, PNU, XI, ETA, PHI)
   p%model = MODEL
   call legacy_solve(p, NX, NY, FX, FY, FMZ, WMAC, WMIC, CK, PX, PY, SX, SY, ZMAP, WPAP, WCON, &
                     ISTATE, IERR, BOX, PZ, PMAX, APPR)
end subroutine CWSOLX

! Forces, moment and macro work of one contact (as CWSOLM: Kalker's strip
! grid, parabolic pressure, flexibilities from G and PNU) and their
! Jacobian for implicit integrators (doc/theory/jacobians.md):
!   DFJ(I, J) = d(output I)/d(input J), I = 1..4: FX, FY, FMZ, WMAC;
!               J = 1..4: XI, ETA, PHI, FN  (SI units: N, N m, J/m per
!               unit creepage, per 1/m of spin, per N)
! exact derivatives of the discrete FASTSIM march (a, b, mu, G, nu held
! fixed). FN must be > 0 when FMU > 0. IERR as CWSOLM; on error nothing is
! written.
subroutine CWJACO(A, B, FN, FMU, G, PNU, XI, ETA, PHI, NX, NY, FX, FY, FMZ, WMAC, DFJ, IERR)
   use, intrinsic :: iso_c_binding, only: c_double, c_int
   use creepwork, only: cw_params, cw_result, cw_solver_type, CW_SOLVE_FORCES, CW_OK, &
                        CW_ERR_INVALID_INPUT
   use creepwork_legacy_support, only: any_subnormal, material_params
   implicit none
   real(c_double), intent(in) :: A, B, FN, FMU, G, PNU, XI, ETA, PHI
   integer(c_int), intent(in) :: NX, NY
   real(c_double), intent(inout) :: FX, FY, FMZ, WMAC
   real(c_double), intent(inout) :: DFJ(4, 4)
   integer(c_int), intent(out) :: IERR
   type(cw_params) :: p
   type(cw_result) :: r
   type(cw_solver_type) :: solver
   real(c_double) :: jac(4, 4)
   integer :: stat
   if (any_subnormal([A, B, FN, FMU, G, PNU, XI, ETA, PHI])) then
      IERR = CW_ERR_INVALID_INPUT
      return
   end if
   p = material_params(A, B, FN, FMU, G, PNU, XI, ETA, PHI)
   call solver%create(nx=NX, ny=NY, stat=stat)
   IERR = int(stat, c_int)
   if (IERR /= CW_OK) return
   call solver%solve_jacobian(p, jac, CW_SOLVE_FORCES, r, stat=stat)
   if (stat == CW_OK) then
      FX = r%Fx
      FY = r%Fy
      FMZ = r%Mz
      WMAC = r%W_macro
      DFJ = jac
   end if
   IERR = int(stat, c_int)
   call solver%destroy()
end subroutine CWJACO

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
   use creepwork, only: CW_OK, CW_ERR_GRID_OUT_OF_RANGE, CW_ERR_INVALID_INPUT, CW_ERR_NUMERIC, &
                        CW_MAX_GRID_CELLS
   use creepwork_legacy_support, only: subnormal, any_subnormal, flushed
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
   if (NX < 1 .or. NX > CW_MAX_GRID_CELLS .or. NY < 1 .or. NY > CW_MAX_GRID_CELLS) then
      IERR = CW_ERR_GRID_OUT_OF_RANGE
      return
   end if
   ! Subnormal inputs are read by nothing (they would trip a denormal trap).
   if (any_subnormal([DIST, WMAC, WMIC, DSUM, WMSUM, WPSUM]) .or. any(subnormal(WPAP)) .or. &
       any(subnormal(WCON)) .or. any(subnormal(WPACC)) .or. any(subnormal(WCACC))) then
      IERR = CW_ERR_INVALID_INPUT
      return
   end if
   if (.not. (ieee_is_finite(DIST) .and. DIST >= 0.0_c_double)) then
      IERR = CW_ERR_INVALID_INPUT
      return
   end if
   d = flushed(DSUM + DIST)
   wm = flushed(WMSUM + flushed(WMAC*DIST))
   wp = flushed(WPSUM + flushed(WMIC*DIST))
   k = 0.0_c_double
   if (wp /= 0.0_c_double) k = flushed(wm/wp)
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
         WPACC(i, j) = flushed(WPACC(i, j) + flushed(DIST*WPAP(i, j)))
         WCACC(i, j) = flushed(WCACC(i, j) + flushed(DIST*WCON(i, j)))
      end do
   end do
   DSUM = d
   WMSUM = wm
   WPSUM = wp
   CKRUN = k
   IERR = CW_OK
end subroutine cwaccu_body

! Kalker's creepage and spin coefficients (Kalker 1990, Table E.3;
! asymptotes below min(a/b, b/a) = 0.1), as cw_kalker_coefficients:
!   AOB       semi-axis ratio a/b [-], 1e-3 .. 1e3
!   PNU       Poisson's ratio [-], 0 .. 0.5
!   C11, C22, C23, C33  (out) the coefficients [-]
!   IERR      0 or CW_ERR_INVALID_INPUT (outputs unchanged)
subroutine CWKALK(AOB, PNU, C11, C22, C23, C33, IERR)
   use, intrinsic :: iso_c_binding, only: c_double, c_int
   use creepwork, only: cw_kalker_coefficients, CW_OK, CW_ERR_INVALID_INPUT
   use creepwork_legacy_support, only: any_subnormal
   implicit none
   real(c_double), intent(in) :: AOB, PNU
   real(c_double), intent(inout) :: C11, C22, C23, C33
   integer(c_int), intent(out) :: IERR
   real(c_double) :: c(4)
   integer :: stat
   if (any_subnormal([AOB, PNU])) then
      IERR = CW_ERR_INVALID_INPUT
      return
   end if
   c = 0.0_c_double
   call cw_kalker_coefficients(AOB, PNU, c, stat=stat)
   IERR = int(stat, c_int)
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
   use creepwork, only: cw_kalker_flexibilities, CW_OK, CW_ERR_INVALID_INPUT
   use creepwork_legacy_support, only: any_subnormal
   implicit none
   real(c_double), intent(in) :: A, B, G, PNU
   real(c_double), intent(inout) :: FL1, FL2, FL3
   integer(c_int), intent(out) :: IERR
   real(c_double) :: L(3)
   integer :: stat
   if (any_subnormal([A, B, G, PNU])) then
      IERR = CW_ERR_INVALID_INPUT
      return
   end if
   L = 0.0_c_double
   call cw_kalker_flexibilities(A, B, G, PNU, L, stat=stat)
   IERR = int(stat, c_int)
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
   use creepwork, only: cw_hertz_solve, CW_OK, CW_ERR_INVALID_INPUT
   use creepwork_legacy_support, only: any_subnormal
   implicit none
   real(c_double), intent(in) :: GA, GB, FN, ESTAR
   real(c_double), intent(inout) :: A, B, P0, APPR
   integer(c_int), intent(out) :: IERR
   real(c_double) :: h(4)
   integer :: stat
   if (any_subnormal([GA, GB, FN, ESTAR])) then
      IERR = CW_ERR_INVALID_INPUT
      return
   end if
   h = 0.0_c_double
   call cw_hertz_solve(GA, GB, FN, ESTAR, h, stat=stat)
   IERR = int(stat, c_int)
   if (IERR /= CW_OK) return
   A = h(1)
   B = h(2)
   P0 = h(3)
   APPR = h(4)
end subroutine CWHERT

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
                        cw_wear_params_init, cw_wear_result, CW_SOLVE_FULL, CW_OK, &
                        CW_ERR_INVALID_INPUT, CW_ERR_GRID_OUT_OF_RANGE, CW_MAX_GRID_CELLS
   use creepwork_legacy_support, only: any_subnormal, material_params
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
   real(c_double) :: y(NY), dy(NY), d(NY)
   integer :: stat
   if (NX < 1 .or. NX > CW_MAX_GRID_CELLS .or. NY < 1 .or. NY > CW_MAX_GRID_CELLS) then
      IERR = CW_ERR_GRID_OUT_OF_RANGE
      return
   end if
   if (any_subnormal([A, B, FN, FMU, G, PNU, XI, ETA, PHI, V])) then
      IERR = CW_ERR_INVALID_INPUT
      return
   end if
   p = material_params(A, B, FN, FMU, G, PNU, XI, ETA, PHI)
   call cw_wear_params_init(wp)
   wp%law = LAW
   wp%rolling_speed = V
   call solver%create(nx=NX, ny=NY, stat=stat)
   if (stat == CW_OK) call solver%solve(p, CW_SOLVE_FULL, stat=stat)
   if (stat == CW_OK) call wear%create(solver, stat=stat)
   if (stat == CW_OK) call wear%compute(solver, wp, r, stat=stat)
   if (stat == CW_OK) call wear%get_strips(y=y, width=dy, depth=d, stat=stat)
   if (stat == CW_OK) then
      YS = y
      DYS = dy
      DEPTH = d
      WMASS = r%mass_per_distance
   end if
   IERR = int(stat, c_int)
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
   use creepwork, only: cw_wear_profile_type, CW_OK, CW_ERR_INVALID_INPUT, CW_ERR_NUMERIC, &
                        CW_WEAR_DEPTH_NORMAL, CW_WEAR_DEPTH_HEIGHT, CW_WEAR_MAX_PROFILE_NODES
   use creepwork_legacy_support, only: any_subnormal, flushed
   implicit none
   integer(c_int), intent(in) :: NS, NY, IORI
   real(c_double), intent(in) :: S(NS), YS(NY), DYS(NY), DEPTH(NY), S0, GAMMA, PASSES
   real(c_double), intent(inout) :: PDN(NS), PDH(NS)
   integer(c_int), intent(out) :: IERR
   type(cw_wear_profile_type) :: profile
   real(c_double), allocatable :: dn(:), dh(:)
   integer :: stat
   if (NS < 2 .or. NS > CW_WEAR_MAX_PROFILE_NODES .or. NY < 1 .or. NY > 1000) then
      IERR = CW_ERR_INVALID_INPUT
      return
   end if
   if (any_subnormal([S0, GAMMA, PASSES]) .or. any_subnormal(S) .or. any_subnormal(YS) .or. &
       any_subnormal(DYS) .or. any_subnormal(DEPTH) .or. any_subnormal(PDN) .or. &
       any_subnormal(PDH)) then
      IERR = CW_ERR_INVALID_INPUT
      return
   end if
   if (.not. (all(ieee_is_finite(PDN)) .and. all(ieee_is_finite(PDH)))) then
      IERR = CW_ERR_INVALID_INPUT
      return
   end if
   allocate (dn(NS), dh(NS))
   call profile%create(S, stat=stat)
   if (stat == CW_OK) call profile%add_strips(YS, DYS, DEPTH, S0, int(IORI), GAMMA, PASSES, &
                                              stat=stat)
   if (stat == CW_OK) call profile%get_depth(CW_WEAR_DEPTH_NORMAL, dn, stat=stat)
   if (stat == CW_OK) call profile%get_depth(CW_WEAR_DEPTH_HEIGHT, dh, stat=stat)
   call profile%destroy()
   IERR = int(stat, c_int)
   if (IERR /= CW_OK) return
   if (.not. (all(ieee_is_finite(PDN + dn)) .and. all(ieee_is_finite(PDH + dh)))) then
      IERR = CW_ERR_NUMERIC
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
   use creepwork, only: cw_wear_profile_update, CW_ERR_INVALID_INPUT, CW_WEAR_MAX_PROFILE_NODES
   use creepwork_legacy_support, only: any_subnormal
   implicit none
   integer(c_int), intent(in) :: NS
   real(c_double), intent(in) :: S(NS), POLD(NS), PDEP(NS), SMOOTH
   real(c_double), intent(inout) :: PNEW(NS)
   integer(c_int), intent(out) :: IERR
   integer :: stat
   if (NS < 2 .or. NS > CW_WEAR_MAX_PROFILE_NODES) then
      IERR = CW_ERR_INVALID_INPUT
      return
   end if
   if (any_subnormal([SMOOTH]) .or. any_subnormal(S) .or. any_subnormal(POLD) .or. &
       any_subnormal(PDEP)) then
      IERR = CW_ERR_INVALID_INPUT
      return
   end if
   call cw_wear_profile_update(S, POLD, PDEP, SMOOTH, PNEW, stat=stat)
   IERR = int(stat, c_int)
end subroutine CWWUPD

! The message of a status: MSG (CHARACTER*(*), any length; 80 holds every
! message) receives cw_status_string(IERR), blank-padded or cut.
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
   implicit none
   real(c_double), intent(in) :: R(2)
   integer(c_int), intent(in) :: N(2)
   integer(c_int), intent(out) :: IERR
   integer(c_int64_t) :: bits
   ! Two REAL*4 (1.0, 2.0) read as one REAL*8 are 2.0000004731118679; a
   ! REAL*16 1.0 has zero low bytes; INTEGER*8 (1, 2) reads as (1, 0).
   ! Compared as bits: garbage may be a NaN, and comparing a NaN traps.
   IERR = CW_ERR_INVALID_INPUT
   bits = transfer(R(1), bits)
   if (bits /= transfer(1.0_c_double, bits)) return
   if (N(1) /= 1_c_int .or. N(2) /= 2_c_int) return
   IERR = CW_OK
end subroutine CWTYPE
