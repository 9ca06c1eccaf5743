! Surface temperature and damage indices through module creepwork:
!   structs      c_sizeof of the bind(C) mirrors equals the struct_size the C
!                _init functions write; the defaults land in the right fields
!   temperature  cw_temperature_type on a solve: one surface temperature in
!                contact for dissimilar bodies, T_c = (b1 T0_1 + b2 T0_2)/(b1
!                + b2), the heat = V x the work map's sum, the maxima are the
!                fields' largest contact values; errors through stat/errmsg
!   mu(T)        cw_temperature_type%solve: CONTACT's euro_tractcurv at 25 %
!                creepage (L=6, -0.19 over 400 deg C; Fx/(0.33 N) = -0.6108,
!                T_max 364.7 deg C, tests/data/temperature) within the C
!                test's tolerances; unsorted points and arrays of different
!                lengths refused naming them
!   damage       cw_damage_type in full sliding: the RCF index mu - k/pz,
!                sum of the T_gamma density x area = W_macro, FI_surf
!   legacy       CWTEMP equals cw_temperature_type on the same solve (V
!                given as cw_params.V), bitwise; errors leave its outputs
!   checks       cw_temperature_params_check, cw_damage_params_check: steel's
!                defaults find nothing; a conductivity in W/(mm K), 300 km/h
!                typed as m/s, k_yield in MPa and a WLRM threshold in kN are
!                named with the library's message (the header's thresholds)
program test_fortran_surface
   use, intrinsic :: iso_c_binding, only: c_double, c_int, c_sizeof
   use creepwork
   use cw_test_support
   implicit none
   include 'creepwork_legacy.fi'

   integer, parameter :: nx = 16, ny = 12
   real(c_double), parameter :: pi = 3.14159265358979323846_c_double

   call check_structs()
   call check_temperature()
   call check_mu_temperature()
   call check_damage()
   call check_plausibility()
   call check_legacy()
   call test_summary('test_fortran_surface')

contains

   subroutine check_structs()
      type(cw_temperature_params) :: tp
      type(cw_temperature_result) :: tr
      type(cw_damage_params) :: dp
      type(cw_damage_result) :: dr
      call cw_temperature_params_init(tp)
      call cw_temperature_result_init(tr)
      call cw_damage_params_init(dp)
      call cw_damage_result_init(dr)
      call check_int(int(tp%struct_size), int(c_sizeof(tp)), 'sizeof(cw_temperature_params)')
      call check_int(int(tr%struct_size), int(c_sizeof(tr)), 'sizeof(cw_temperature_result)')
      call check_int(int(dp%struct_size), int(c_sizeof(dp)), 'sizeof(cw_damage_params)')
      call check_int(int(dr%struct_size), int(c_sizeof(dr)), 'sizeof(cw_damage_result)')
      call check_same(tp%T0_1, 20.0_c_double, 'default T0_1')
      call check_same(tp%density_2, 7850.0_c_double, 'default density_2')
      call check_int(tp%rolling_direction, 1, 'default rolling_direction')
      call check_int(tp%discretisation, CW_TEMPERATURE_CONSISTENT, 'default discretisation')
      call check_same(dp%wlrm_zero, 175.0_c_double, 'default wlrm_zero')
      call check_same(dp%wlrm_peak_damage, 1e-5_c_double, 'default wlrm_peak_damage (last)')
   end subroutine check_structs

   subroutine solved(solver, xi)
      type(cw_solver_type), intent(inout) :: solver
      real(c_double), intent(in) :: xi
      type(cw_params) :: p
      call cw_params_init(p)
      p%a = 6e-3_c_double
      p%b = 4e-3_c_double
      p%normal_force = 60e3_c_double
      p%mu = 0.35_c_double
      p%xi_x = xi
      p%xi_y = -5e-4_c_double
      p%phi = 0.8_c_double
      p%rolling_direction = -1
      call solver%solve(p, CW_SOLVE_FULL)
   end subroutine solved

   subroutine check_temperature()
      type(cw_solver_type) :: solver
      type(cw_temperature_type) :: temperature
      type(cw_temperature_params) :: tp
      type(cw_temperature_result) :: tr
      type(cw_result) :: r
      real(c_double) :: rail(nx, ny), wheel(nx, ny), heat(nx*ny)
      integer(c_int) :: state(nx, ny)
      real(c_double) :: b1, b2
      character(len=:), allocatable :: msg
      integer :: stat
      call solver%create(kind=CW_GRID_UNIFORM, nx=nx, ny=ny, box_scale=1.2_c_double)
      call solved(solver, 1.5e-3_c_double)
      call solver%get_result(r)
      call temperature%create(solver)
      call cw_temperature_params_init(tp)
      tp%T0_1 = 10
      tp%T0_2 = 70
      tp%conductivity_2 = 200      ! beta2 = 2 beta1
      tp%rolling_speed = 40
      tp%rolling_direction = -1
      call temperature%compute(solver, tp, tr)
      call temperature%get_field(CW_TEMPERATURE_FIELD_RAIL, rail)
      call temperature%get_field(CW_TEMPERATURE_FIELD_WHEEL, wheel)
      call temperature%get_field(CW_TEMPERATURE_FIELD_HEAT, heat)
      call solver%get_state(state)
      b1 = sqrt(tp%conductivity_1*tp%density_1*tp%heat_capacity_1)
      b2 = sqrt(tp%conductivity_2*tp%density_2*tp%heat_capacity_2)
      call check_close(tr%contact_temperature, (b1*10 + b2*70)/(b1 + b2), 1e-14_c_double, &
                       0.0_c_double, 'T_c = (b1 T0_1 + b2 T0_2)/(b1 + b2)')
      call check_true(all(pack(rail, state >= 1) == pack(wheel, state >= 1)), &
                      'one surface temperature in contact')
      call check_same(tr%T_max_1, maxval(pack(rail, state >= 1)), 'T_max_1 = largest contact value')
      call check_same(tr%T_max_2, maxval(pack(wheel, state >= 1)), 'T_max_2 = largest contact value')
      call check_close(tr%power, 40*r%W_consistent, 1e-12_c_double, 0.0_c_double, &
                       'heat = V x the work map''s sum')
      call check_true(all(heat >= 0), 'heat >= 0')
      tr%T_max_1 = -1
      call temperature%get_result(tr)
      call check_same(tr%T_max_1, maxval(pack(rail, state >= 1)), 'get_result')
      ! errors through stat and errmsg
      tp%conductivity_1 = -1
      call temperature%compute(solver, tp, stat=stat, errmsg=msg)
      call check_int(stat, CW_ERR_INVALID_INPUT, 'conductivity_1 < 0')
      call check_true(index(msg, 'conductivity_1') > 0, 'message names conductivity_1: '//msg)
      rail = -1
      call temperature%get_field(CW_TEMPERATURE_FIELD_RAIL, rail, stat=stat)
      call check_int(stat, CW_ERR_NO_SOLUTION, 'no temperature after a failed compute')
      call check_true(all(rail == -1), 'rail untouched')
      call temperature%destroy()
      call solver%destroy()
   end subroutine check_temperature

   subroutine check_mu_temperature()
      type(cw_solver_type) :: solver
      type(cw_temperature_type) :: temperature
      type(cw_temperature_params) :: tp
      type(cw_temperature_result) :: tr
      type(cw_params) :: p
      type(cw_result) :: r
      real(c_double) :: T(2), mu(2), mu3(3)
      character(len=:), allocatable :: msg
      integer :: stat
      call solver%create(kind=CW_GRID_UNIFORM, nx=44, ny=44, box_scale=1.1_c_double)
      call temperature%create(solver)
      call cw_params_init(p)
      p%model = CW_MODEL_EXACT
      p%a = 6.304e-3_c_double
      p%b = 12.61e-3_c_double
      p%normal_force = 106.7e3_c_double
      p%V = 10
      p%xi_x = 0.25_c_double
      call cw_temperature_params_init(tp)
      tp%T0_1 = 0
      tp%T0_2 = 0
      tp%discretisation = CW_TEMPERATURE_CONTACT
      T = [0.0_c_double, 400.0_c_double]
      mu = [0.33_c_double, 0.14_c_double]
      call temperature%solve(solver, p, tp, T, mu, r, tr)
      call check_close(r%Fx/(0.33_c_double*p%normal_force), -0.6108_c_double, 0.0_c_double, &
                       5.5e-4_c_double, 'euro_tractcurv 25 %: Fx/(FREF N)')
      call check_close(max(tr%T_max_1, tr%T_max_2), 364.7_c_double, 2e-3_c_double, &
                       0.05_c_double, 'euro_tractcurv 25 %: T_max')
      call check_true(tr%iterations >= 2, 'passes of solve and temperature')
      T = [400.0_c_double, 0.0_c_double]
      call temperature%solve(solver, p, tp, T, mu, stat=stat, errmsg=msg)
      call check_int(stat, CW_ERR_INVALID_INPUT, 'unsorted temperatures')
      call check_true(index(msg, 'temperature[1]') > 0, 'message names temperature[1]: '//msg)
      T = [0.0_c_double, 400.0_c_double]
      mu3 = 0.3_c_double
      call temperature%solve(solver, p, tp, T, mu3, stat=stat, errmsg=msg)
      call check_int(stat, CW_ERR_INVALID_INPUT, 'lengths differ')
      call check_true(index(msg, 'mu_T') > 0, 'message names mu_T: '//msg)
      call temperature%destroy()
      call solver%destroy()
   end subroutine check_mu_temperature

   subroutine check_damage()
      type(cw_solver_type) :: solver
      type(cw_damage_type) :: damage
      type(cw_damage_params) :: dp
      type(cw_damage_result) :: dr
      type(cw_result) :: r
      real(c_double) :: rcf(nx, ny), density(nx, ny), area(nx, ny), pz(nx, ny), expect(nx, ny)
      integer(c_int) :: state(nx, ny)
      character(len=:), allocatable :: msg
      integer :: stat
      call solver%create(kind=CW_GRID_UNIFORM, nx=nx, ny=ny, box_scale=1.2_c_double)
      call solved(solver, 0.05_c_double) ! full sliding
      call solver%get_result(r)
      call check_int(r%n_adhesion, 0, 'full sliding')
      call damage%create(solver)
      call cw_damage_params_init(dp)
      call damage%compute(solver, dp, dr, stat=stat, errmsg=msg)
      call check_int(stat, CW_ERR_INVALID_INPUT, 'k_yield not set')
      call check_true(index(msg, 'k_yield') > 0, 'message names k_yield: '//msg)
      dp%k_yield = 250e6_c_double
      call damage%compute(solver, dp, dr)
      call damage%get_field(CW_DAMAGE_FIELD_RCF_INDEX, rcf)
      call damage%get_field(CW_DAMAGE_FIELD_T_GAMMA_DENSITY, density)
      call solver%get_field(CW_FIELD_AREA, area)
      call solver%get_field(CW_FIELD_PZ, pz)
      call solver%get_state(state)
      expect = -0.5_c_double
      where (state >= 1 .and. pz > 0) expect = max(-0.5_c_double, 0.35_c_double - 250e6_c_double/pz)
      call check_true(maxval(abs(rcf - expect)) <= 1e-12_c_double, &
                      'RCF index = max(-0.5, mu - k/pz) in full sliding')
      call check_close(sum(density*area), r%W_macro, 1e-12_c_double, 0.0_c_double, &
                       'sum T_gamma density x area = W_macro')
      call check_close(dr%FI_surf, hypot(r%Fx, r%Fy)/60e3_c_double - &
                       2*pi*r%a*r%b*250e6_c_double/(3*60e3_c_double), 1e-13_c_double, &
                       1e-15_c_double, 'FI_surf = mu_eff - 2 pi a b k/(3 N)')
      call check_same(dr%T_gamma, r%W_macro, 'T_gamma = W_macro')
      call damage%destroy()
      call solver%destroy()
   end subroutine check_damage

   subroutine check_plausibility()
      type(cw_temperature_params) :: tp
      type(cw_damage_params) :: dp
      type(cw_check), allocatable :: checks(:)
      integer :: stat
      call cw_temperature_params_init(tp)
      tp%rolling_speed = 30.0_c_double
      call cw_temperature_params_check(tp, checks, stat=stat)
      call check_int(stat, CW_OK, 'temperature check: stat')
      call check_int(size(checks), 0, 'steel at 30 m/s: no finding')
      tp%conductivity_2 = 0.05_c_double ! W/(mm K) typed: 1 W/(m K) is the bound
      tp%rolling_speed = 300.0_c_double ! km/h typed: 150 m/s is the bound
      call cw_temperature_params_check(tp, checks)
      call check_int(size(checks), 2, 'two findings')
      call check_int(int(checks(1)%rule), CW_CHECK_CONDUCTIVITY, 'conductivity: the rule')
      call check_string(cw_check_text(checks(1)%message), 'conductivity_2 = 0.05 W/(m K) is '// &
                        'implausible for a wheel-rail contact: '//cw_check_text(checks(1)%reason), &
                        'conductivity: the message')
      call check_true(index(cw_check_text(checks(1)%reason), 'W/(mm K) typed') > 0, &
                      'conductivity: the mistake')
      call check_int(int(checks(2)%rule), CW_CHECK_SPEED, 'rolling speed: the rule')
      call check_string(cw_check_text(checks(2)%input), 'rolling_speed', 'rolling speed: the input')
      call check_same(checks(2)%value, 300.0_c_double, 'rolling speed: the value')
      call cw_damage_params_init(dp)
      dp%k_yield = 3e8_c_double
      call cw_damage_params_check(dp, checks)
      call check_int(size(checks), 0, 'k_yield 3e8 Pa, Burstow''s thresholds: no finding')
      dp%k_yield = 300.0_c_double ! MPa typed: 1e6 Pa is the bound
      dp%wlrm_zero = 0.175_c_double ! kN typed: 1 N is the bound
      call cw_damage_params_check(dp, checks, stat=stat)
      call check_int(stat, CW_OK, 'damage check: stat')
      call check_int(size(checks), 2, 'k_yield and wlrm_zero')
      call check_int(int(checks(1)%rule), CW_CHECK_YIELD_STRESS, 'k_yield: the rule')
      call check_true(index(cw_check_text(checks(1)%message), 'k_yield = 300 Pa is implausible') == 1, &
                      'k_yield: the message')
      call check_int(int(checks(2)%rule), CW_CHECK_WLRM_THRESHOLD, 'wlrm_zero: the rule')
      call check_string(cw_check_text(checks(2)%input), 'wlrm_zero', 'wlrm_zero: the input')
      dp%struct_size = 0
      call cw_damage_params_check(dp, checks, stat=stat)
      call check_int(stat, CW_ERR_STRUCT_SIZE, 'not initialised: stat')
      call check_int(size(checks), 0, 'not initialised: no findings')
   end subroutine check_plausibility

   ! CWTEMP = module on the same contact (CWSOLM's: flexibilities from G and
   ! nu, rolling towards +x), with the speed as the solve's cw_params.V.
   subroutine check_legacy()
      type(cw_solver_type) :: solver
      type(cw_temperature_type) :: t
      type(cw_params) :: p
      type(cw_temperature_params) :: tp
      type(cw_temperature_result) :: r
      real(c_double) :: T1(nx, ny), T2(nx, ny), rail(nx, ny), wheel(nx, ny)
      real(c_double) :: tmax(2), xmax(2), ymax(2)
      integer(c_int) :: ierr
      call CWTEMP(6e-3_c_double, 4e-3_c_double, 60e3_c_double, 0.35_c_double, 82e9_c_double, &
                  0.28_c_double, 2e-3_c_double, -1e-3_c_double, 1.5_c_double, int(nx, c_int), &
                  int(ny, c_int), 30.0_c_double, 10.0_c_double, 70.0_c_double, T1, T2, tmax, &
                  xmax, ymax, ierr)
      call check_int(int(ierr), CW_OK, 'CWTEMP')
      call cw_params_init(p)
      p%a = 6e-3_c_double
      p%b = 4e-3_c_double
      p%normal_force = 60e3_c_double
      p%mu = 0.35_c_double
      p%G = 82e9_c_double
      p%nu = 0.28_c_double
      p%xi_x = 2e-3_c_double
      p%xi_y = -1e-3_c_double
      p%phi = 1.5_c_double
      call solver%create(nx=nx, ny=ny)
      call solver%solve(p, CW_SOLVE_FULL)
      call t%create(solver)
      call cw_temperature_params_init(tp)
      tp%T0_1 = 10
      tp%T0_2 = 70
      tp%rolling_speed = 30
      call t%compute(solver, tp, r)
      call t%get_field(CW_TEMPERATURE_FIELD_RAIL, rail)
      call t%get_field(CW_TEMPERATURE_FIELD_WHEEL, wheel)
      call check_true(all(T1 == rail) .and. all(T2 == wheel), 'CWTEMP fields = module, bitwise')
      call check_true(tmax(1) == r%T_max_1 .and. tmax(2) == r%T_max_2, 'CWTEMP maxima = module')
      call check_true(xmax(1) == r%x_max_1 .and. ymax(1) == r%y_max_1 .and. &
                      xmax(2) == r%x_max_2 .and. ymax(2) == r%y_max_2, 'CWTEMP positions = module')
      call check_true(tmax(1) > 30, 'CWTEMP heats')
      ! errors leave the outputs alone and name the input
      T1 = -7
      call CWTEMP(6e-3_c_double, 4e-3_c_double, 60e3_c_double, 0.35_c_double, 82e9_c_double, &
                  0.28_c_double, 2e-3_c_double, -1e-3_c_double, 1.5_c_double, int(nx, c_int), &
                  int(ny, c_int), 0.0_c_double, 10.0_c_double, 70.0_c_double, T1, T2, tmax, &
                  xmax, ymax, ierr)
      call check_int(int(ierr), CW_ERR_INVALID_INPUT, 'CWTEMP with V = 0')
      call check_true(all(T1 == -7), 'CWTEMP outputs untouched on error')
      call CWTEMP(6e-3_c_double, 4e-3_c_double, 60e3_c_double, 0.35_c_double, 82e9_c_double, &
                  0.28_c_double, 2e-3_c_double, -1e-3_c_double, 1.5_c_double, int(nx, c_int), &
                  int(ny, c_int), 30.0_c_double, -300.0_c_double, 70.0_c_double, T1, T2, tmax, &
                  xmax, ymax, ierr)
      call check_int(int(ierr), CW_ERR_INVALID_INPUT, 'CWTEMP with T01 below absolute zero')
      call t%destroy()
      call solver%destroy()
   end subroutine check_legacy

end program test_fortran_surface
