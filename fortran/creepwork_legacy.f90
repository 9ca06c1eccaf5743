! creepwork_legacy.f90 -- the FORTRAN-77-callable layer of libcreepwork_fortran:
! the contact solves (this file); creepwork_legacy_tools.f90 has the work
! accumulation, Kalker's coefficients and flexibilities, Hertz, the messages
! and the kind check; creepwork_legacy_wear.f90 the wear routines,
! creepwork_legacy_surface.f90 the surface temperature,
! creepwork_legacy_friction.f90 the friction laws of the slip speed.
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
!   CWFORC  forces, moment, macro work and adhesion only, on a solver kept
!           per thread and grid shape: the call for time loops
!   CWFREE  frees the calling thread's CWFORC solvers
!   CWACCU  adds one time step's work into running totals (paper eqs. 35, 37)
!   CWKALK  Kalker's creepage and spin coefficients C11, C22, C23, C33
!   CWFLEX  Kalker's flexibilities L1, L2, L3 (for CWSOLL and CWFSIM)
!   CWHERT  Hertz: semi-axes, peak pressure and approach from the gap
!   CWWEAR  wear of one contact (USFD or Archard/KTH): depth per pass per strip
!   CWWPRF  adds passes of a lateral wear profile to a profile grid's depths
!   CWWUPD  profile update: new = old - (smoothed) depth
!   CWTEMP  surface temperature of both bodies of one contact, their maxima
!   CWFLAW  forces of one contact under a friction law of the slip speed
!   CWFMEM  CWFLAW with friction memory and an interface layer
!   CWERRM  the message of an IERR value
!   CWLAST  the detailed message of the calling thread's last call, naming
!           the offending input
!   CWTYPE  checks that the caller's REAL and INTEGER are the library's
!
! The installed include/creepwork/fortran/creepwork_legacy.inc declares them
! EXTERNAL with every argument listed; creepwork_legacy.fi has interface
! blocks (free form) that let the compiler check every call.
!
! Messages: every routine with an IERR leaves the calling thread's last
! message, '' after a success and the detailed message after an error
! (e.g. "an input value is invalid (NaN, Inf, out of range): nu = 0.6 is
! invalid: must lie in [0, 0.5]"); CALL CWLAST(MSG) reads it. Each thread has
! its own (legacy_thread_state.cpp), so threads do not see each other's.
!
! Cost: CWSOLM, CWSOLL, CWSOLX, CWJACO, CWWEAR and CWTEMP make and free a solver in
! every call and fill every map: no state, any grid from call to call, but
! several times a forces-only solve on a reused solver (the benchmark
! creepwork_bench_legacy measures both). CWFORC keeps one solver per grid
! shape and thread and costs about that solve. Loops that want the maps
! without the allocation use module creepwork (cw_solver_type).
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
! need no declarations except CHARACTER for CWERRM's and CWLAST's message.
! Arrays are dimensioned exactly (NX, NY) in the caller (element I along x,
! the rolling direction, J along y), as in the C layout. The routines keep no
! state but the thread's message and CWFORC's solvers, and may be called
! from several threads at once.
!
! Floating-point traps: every routine is safe in a program built with
! -ffpe-trap=invalid,zero,overflow,denormal. The library's calls mask and
! restore the floating-point state themselves (doc/reference/guarantees.md); the
! arithmetic done here (CWACCU, CWWPRF) runs with halting off and restores the
! caller's halting modes and flags (IEEE_GET_STATUS/IEEE_SET_STATUS), and
! reads no subnormal number: such inputs are rejected, such results are 0.

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
   use creepwork, only: cw_fastsim_normalised, CW_OK
   use creepwork_legacy_support, only: check_normal, remember
   implicit none
   real(c_double), intent(in) :: UX, UY, FX, FY, TOL
   integer(c_int), intent(in) :: MX, MY
   real(c_double), intent(inout) :: TX, TY
   integer(c_int), intent(out) :: IERR
   character(len=:), allocatable :: message
   integer :: stat
   call check_normal([UX, UY, FX, FY, TOL], 'UX UY FX FY TOL', IERR)
   if (IERR /= CW_OK) return
   call cw_fastsim_normalised(UX, UY, FX, FY, int(MX), int(MY), TOL, TX, TY, stat=stat, &
                              errmsg=message)
   IERR = int(stat, c_int)
   call remember(message)
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
! Cost: a solver made and freed and every map filled per call, several times
! a reused solver's solve ("Cost" above); forces in a time loop: CWFORC.
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
   use creepwork, only: cw_params, cw_result, cw_solver_type, CW_SOLVE_FORCES, CW_OK
   use creepwork_legacy_support, only: check_normal, material_params, remember
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
   character(len=:), allocatable :: message
   integer :: stat
   call check_normal([A, B, FN, FMU, G, PNU, XI, ETA, PHI], 'A B FN FMU G PNU XI ETA PHI', IERR)
   if (IERR /= CW_OK) return
   p = material_params(A, B, FN, FMU, G, PNU, XI, ETA, PHI)
   call solver%create(nx=NX, ny=NY, stat=stat, errmsg=message)
   if (stat == CW_OK) call solver%solve_jacobian(p, jac, CW_SOLVE_FORCES, r, stat=stat, &
                                                 errmsg=message)
   if (stat == CW_OK) then
      FX = r%Fx
      FY = r%Fy
      FMZ = r%Mz
      WMAC = r%W_macro
      DFJ = jac
   end if
   IERR = int(stat, c_int)
   call remember(message)
   call solver%destroy()
end subroutine CWJACO

! Forces only, for time loops: the creep force, moment, macro work and
! adhesion fraction of one contact as CWSOLM computes them (Kalker's strip
! grid, parabolic pressure, flexibilities from G and PNU; bitwise the same
! FX, FY, FMZ, WMAC), without the maps, on a solver the calling thread
! keeps for the grid shape (NX, NY). The first call on a shape makes it (an
! allocation, as every CWSOLM call does); later calls cost about a
! forces-only solve on a reused C solver (creepwork_bench_legacy).
!   A, B, FN, FMU, G, PNU, XI, ETA, PHI, NX, NY   as CWSOLM
!   LOAD      0: the pressure law's analytic scale 2 FN/(pi A B), as CWSOLM
!             (Kalker's algorithm; its discrete load differs from FN by up
!             to a few tenths of a per cent); 1: the pressure scaled so that
!             the discrete load sum(pz dA) is FN exactly, so that
!             |F| <= FMU FN to rounding in saturation (cw_params.exact_load)
! Outputs (on the wheel, as CWSOLM):
!   FX, FY    creep force [N];  FMZ  creep moment about the centre [N m]
!   WMAC      macro work -(FX XI + FY ETA + FMZ PHI) [J/m] (paper eq. 34)
!   ADH       adhesion fraction: adhesion elements / contact elements [-]
!   IERR      0 or a CW_* status (outputs unchanged)
! Solvers kept: per thread, the last 4 grid shapes used (a fifth shape frees
! the least recently used first), so a host that changes shape on every call
! pays CWSOLM's allocation and never holds more than 4; a solver holds
! about 0.2 kB per element (86 kB at 20 x 20, 170 MB at 1000 x 1000). They
! are freed when the thread ends (the main thread's at program exit) or by
! CALL CWFREE.
subroutine CWFORC(A, B, FN, FMU, G, PNU, XI, ETA, PHI, NX, NY, LOAD, FX, FY, FMZ, WMAC, ADH, &
                  IERR)
   use, intrinsic :: iso_c_binding, only: c_double, c_int
   use creepwork, only: cw_params, cw_grid, cw_grid_init, cw_result, cw_result_init, &
                        CW_SOLVE_FORCES, CW_OK
   use creepwork_legacy_support, only: check_normal, material_params, cwl_solve_cached
   implicit none
   real(c_double), intent(in) :: A, B, FN, FMU, G, PNU, XI, ETA, PHI
   integer(c_int), intent(in) :: NX, NY, LOAD
   real(c_double), intent(inout) :: FX, FY, FMZ, WMAC, ADH
   integer(c_int), intent(out) :: IERR
   type(cw_params) :: p
   type(cw_grid) :: grid
   type(cw_result) :: r
   call check_normal([A, B, FN, FMU, G, PNU, XI, ETA, PHI], 'A B FN FMU G PNU XI ETA PHI', IERR)
   if (IERR /= CW_OK) return
   p = material_params(A, B, FN, FMU, G, PNU, XI, ETA, PHI)
   p%exact_load = LOAD
   call cw_grid_init(grid)
   grid%nx = NX
   grid%ny = NY
   call cw_result_init(r)
   ! The solve sets the thread's message (here '' or the detailed one).
   IERR = cwl_solve_cached(grid, p, CW_SOLVE_FORCES, r)
   if (IERR /= CW_OK) return
   FX = r%Fx
   FY = r%Fy
   FMZ = r%Mz
   WMAC = r%W_macro
   ADH = r%adhesion_fraction
end subroutine CWFORC

! Frees the solvers CWFORC keeps for the calling thread (the next CWFORC
! call makes one again): for a thread that is done with CWFORC but lives
! on, or to give the memory back between the phases of a run.
subroutine CWFREE()
   use creepwork_legacy_support, only: cwl_free_solvers
   implicit none
   call cwl_free_solvers()
end subroutine CWFREE
