! The legacy layer's contact of any shape (doc/fortran-legacy.md, CWSOLG):
! a plain external subroutine over the caller's undeformed distance on a
! regular grid, solved by module creepwork's gap grid (CW_GRID_GAP,
! doc/theory/non-hertzian.md).

! One contact of any shape on the caller's grid: element (I, J) centred at
! X0 + (I-1) DX, Y0 + (J-1) DY, its undeformed distance H(I, J) [m] (> 0
! apart), rolling towards +x:
!   MODEL     0 FASTSIM (each patch with the flexibilities of its own
!             ellipse), 1 Kalker's exact half-space theory (tolerance 1e-8)
!   NMETH     the normal problem: 0 exact (half-space), 1 semi-Hertzian (fast)
!   LOAD      0: FN given, APPR found; 1: APPR given (from H's datum), FN found
!   FN, APPR  normal force [N], approach [m]: the one LOAD names is read,
!             the other written
!   FMU, G, PNU, XI, ETA, PHI  as CWSOLM
! Outputs (on error nothing is written):
!   FX, FY    creep force on the wheel [N];  FMZ  moment about the grid's
!             origin (x = y = 0) [N m];  WMAC  macro work [J/m]
!   PMAX      largest element pressure [Pa];  NPATCH  separate patches
!   PX, PY, PZ  (NX,NY) tractions on the wheel, pressure [Pa]
!   WCON      (NX,NY) energy-consistent local work [J/m]
!   ISTATE    (NX,NY) 0 exterior, 1 adhesion, 2 slip
! Each call makes and frees its own solver (warm starts: module creepwork).
subroutine CWSOLG(MODEL, NMETH, NX, NY, X0, Y0, DX, DY, H, LOAD, FN, APPR, FMU, G, PNU, XI, ETA, &
                  PHI, FX, FY, FMZ, WMAC, PMAX, NPATCH, PX, PY, PZ, WCON, ISTATE, IERR)
   use, intrinsic :: iso_c_binding, only: c_double, c_int, c_loc, c_size_t
   use creepwork
   use creepwork_legacy_support, only: check_array, check_normal, check_range, remember, material_params, &
                                       subnormal
   implicit none
   integer(c_int), intent(in) :: MODEL, NMETH, NX, NY, LOAD
   real(c_double), intent(in) :: X0, Y0, DX, DY, FMU, G, PNU, XI, ETA, PHI
   real(c_double), intent(in), target :: H(NX, NY)
   real(c_double), intent(inout) :: FN, APPR, FX, FY, FMZ, WMAC, PMAX
   integer(c_int), intent(inout) :: NPATCH
   real(c_double), intent(inout), dimension(NX, NY) :: PX, PY, PZ, WCON
   integer(c_int), intent(inout) :: ISTATE(NX, NY)
   integer(c_int), intent(out) :: IERR
   type(cw_solver_type) :: solver
   type(cw_grid) :: grid
   type(cw_params) :: p
   type(cw_result) :: r
   character(len=:), allocatable :: message
   integer :: stat
   call check_range(NX, 'NX', 3, int(CW_MAX_GRID_CELLS), CW_ERR_GRID_OUT_OF_RANGE, IERR)
   if (IERR == CW_OK) call check_range(NY, 'NY', 3, int(CW_MAX_GRID_CELLS), CW_ERR_GRID_OUT_OF_RANGE, IERR)
   if (IERR == CW_OK) call check_range(LOAD, 'LOAD', 0, 1, CW_ERR_UNKNOWN_OPTION, IERR)
   if (IERR == CW_OK) call check_range(NMETH, 'NMETH', 0, 1, CW_ERR_UNKNOWN_OPTION, IERR)
   if (IERR == CW_OK) call check_normal([X0, Y0, DX, DY, FN, APPR, FMU, G, PNU, XI, ETA, PHI], &
                                        'X0 Y0 DX DY FN APPR FMU G PNU XI ETA PHI', IERR)
   if (IERR == CW_OK) call check_array(any(subnormal(H)), 'H', IERR)
   if (IERR /= CW_OK) return
   call cw_grid_init(grid)
   grid%kind = CW_GRID_GAP
   grid%nx = NX
   grid%ny = NY
   grid%x0 = X0
   grid%y0 = Y0
   grid%dx = DX
   grid%dy = DY
   p = material_params(0.0_c_double, 0.0_c_double, FN, FMU, G, PNU, XI, ETA, PHI)
   p%model = MODEL
   p%normal_method = NMETH
   p%normal_load = LOAD
   p%approach = APPR
   if (LOAD == CW_NORMAL_APPROACH) p%normal_force = 0
   p%gap = c_loc(H)
   p%gap_len = int(NX, c_size_t)*int(NY, c_size_t)
   call solver%create(grid=grid, stat=stat, errmsg=message)
   if (stat == CW_OK) call solver%solve(p, CW_SOLVE_FULL, r, stat=stat, errmsg=message)
   if (stat == CW_OK) call solver%get_field(CW_FIELD_PX, PX, stat=stat, errmsg=message)
   if (stat == CW_OK) call solver%get_field(CW_FIELD_PY, PY, stat=stat, errmsg=message)
   if (stat == CW_OK) call solver%get_field(CW_FIELD_PZ, PZ, stat=stat, errmsg=message)
   if (stat == CW_OK) call solver%get_field(CW_FIELD_WORK_CONSISTENT, WCON, stat=stat, errmsg=message)
   if (stat == CW_OK) call solver%get_state(ISTATE, stat=stat, errmsg=message)
   if (stat == CW_OK) then
      FN = r%normal_force
      APPR = r%approach
      FX = r%Fx
      FY = r%Fy
      FMZ = r%Mz
      WMAC = r%W_macro
      PMAX = r%p_max
      NPATCH = r%n_patches
   end if
   IERR = int(stat, c_int)
   call remember(message)
   call solver%destroy()
end subroutine CWSOLG
