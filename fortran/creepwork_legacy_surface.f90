! creepwork_legacy_surface.f90 -- the legacy layer's surface temperature
! (doc/theory/temperature.md; conventions: creepwork_legacy.f90).

! Surface temperature of one contact (doc/theory/temperature.md): solved as
! CWSOLM (rolling towards +x), then both bodies' steady flash temperatures
! from the energy-consistent work map, consistent discretisation, both
! bodies steel (c = 450 J/(kg K), lambda = 50 W/(m K), rho = 7850 kg/m^3).
! Other materials or CONTACT's discretisation: module creepwork
! (cw_temperature_type). Body 1 is the rail, body 2 the wheel.
!   A, B, FN, FMU, G, PNU, XI, ETA, PHI, NX, NY   as CWSOLM
!   V         rolling speed [m/s], in [1e-3, 1e3]
!   T01, T02  bulk temperatures of body 1 and body 2 [deg C]
!   T1, T2    (out) surface temperature of body 1 and body 2 per element
!             [deg C]                                          (NX, NY)
!   TMAX      (out) each body's hottest contact element [deg C]   (2)
!   XMAX, YMAX (out) its centre [m]                               (2)
!   IERR      0 or a CW_* status (outputs unchanged)
! Each call makes and frees its own solver, like CWSOLM.
subroutine CWTEMP(A, B, FN, FMU, G, PNU, XI, ETA, PHI, NX, NY, V, T01, T02, T1, T2, TMAX, &
                  XMAX, YMAX, IERR)
   use, intrinsic :: iso_c_binding, only: c_double, c_int
   use creepwork, only: cw_params, cw_solver_type, cw_temperature_type, cw_temperature_params, &
                        cw_temperature_params_init, cw_temperature_result, CW_SOLVE_FULL, CW_OK, &
                        CW_TEMPERATURE_FIELD_RAIL, CW_TEMPERATURE_FIELD_WHEEL
   use creepwork_legacy_support, only: check_normal, check_cells, material_params, remember
   implicit none
   real(c_double), intent(in) :: A, B, FN, FMU, G, PNU, XI, ETA, PHI, V, T01, T02
   integer(c_int), intent(in) :: NX, NY
   real(c_double), intent(inout), dimension(NX, NY) :: T1, T2
   real(c_double), intent(inout), dimension(2) :: TMAX, XMAX, YMAX
   integer(c_int), intent(out) :: IERR
   type(cw_params) :: p
   type(cw_solver_type) :: solver
   type(cw_temperature_type) :: temperature
   type(cw_temperature_params) :: tp
   type(cw_temperature_result) :: r
   real(c_double), allocatable :: rail(:, :), wheel(:, :)
   character(len=:), allocatable :: message
   integer :: stat
   call check_cells(NX, 'NX', IERR)
   if (IERR == CW_OK) call check_cells(NY, 'NY', IERR)
   if (IERR == CW_OK) call check_normal([A, B, FN, FMU, G, PNU, XI, ETA, PHI, V, T01, T02], &
                                        'A B FN FMU G PNU XI ETA PHI V T01 T02', IERR)
   if (IERR /= CW_OK) return
   allocate (rail(NX, NY), wheel(NX, NY))
   p = material_params(A, B, FN, FMU, G, PNU, XI, ETA, PHI)
   p%V = V ! the temperature takes the solve's rolling speed
   call cw_temperature_params_init(tp)
   tp%T0_1 = T01
   tp%T0_2 = T02
   call solver%create(nx=NX, ny=NY, stat=stat, errmsg=message)
   if (stat == CW_OK) call solver%solve(p, CW_SOLVE_FULL, stat=stat, errmsg=message)
   if (stat == CW_OK) call temperature%create(solver, stat=stat, errmsg=message)
   if (stat == CW_OK) call temperature%compute(solver, tp, r, stat=stat, errmsg=message)
   if (stat == CW_OK) &
      call temperature%get_field(CW_TEMPERATURE_FIELD_RAIL, rail, stat=stat, errmsg=message)
   if (stat == CW_OK) &
      call temperature%get_field(CW_TEMPERATURE_FIELD_WHEEL, wheel, stat=stat, errmsg=message)
   if (stat == CW_OK) then
      T1 = rail
      T2 = wheel
      TMAX = [r%T_max_1, r%T_max_2]
      XMAX = [r%x_max_1, r%x_max_2]
      YMAX = [r%y_max_1, r%y_max_2]
   end if
   IERR = int(stat, c_int)
   call remember(message)
   call temperature%destroy()
   call solver%destroy()
end subroutine CWTEMP
