! Every function of the C ABI through module creepwork, so that the module
! cannot drift from the header unnoticed (check_fortran_bindings.py checks
! that the two lists of symbols agree; this test calls each one):
!   constants   generated from creepwork.h: versions against the library,
!               every status code against cw_status_string
!   structs     c_sizeof of each bind(C) mirror equals the struct_size the C
!               _init function writes; the defaults land in the right fields
!   solver      lifecycle, every field and state, the profile, layout
!               (i along x, j along y), errors with stat/errmsg
!   accumulator paper eqs. 35, 37, 39 on two steps; errors
!   batch       bitwise equal to one-by-one solves; per-contact statuses
!   helpers     Kalker coefficients (Kalker 1990, Table E.3), flexibilities
!               (header formulas), Hertz (circular contact), normalised FASTSIM
! Expected values cite the header (creepwork.h) unless stated otherwise.
program test_fortran_api
   use, intrinsic :: iso_c_binding, only: c_double, c_int, c_int64_t, c_sizeof
   use creepwork
   use cw_test_support
   implicit none

   real(c_double), parameter :: pi = 3.14159265358979323846_c_double
   integer, parameter :: nx = 12, ny = 9

   call check_constants()
   call check_structs()
   call check_solver()
   call check_accumulator()
   call check_batch()
   call check_helpers()
   call test_summary('test_fortran_api')

contains

   subroutine check_constants()
      character(len=32) :: expected
      integer :: k
      call check_int(cw_library_version_number(), CW_VERSION_NUMBER, 'cw_version_number()')
      call check_int(CW_VERSION_NUMBER, 10000*CW_VERSION_MAJOR + 100*CW_VERSION_MINOR + &
                     CW_VERSION_PATCH, 'CW_VERSION_NUMBER = 10000 major + 100 minor + patch')
      call check_int(cw_library_abi_version(), CW_ABI_VERSION, 'cw_abi_version()')
      write (expected, '(i0,".",i0,".",i0)') CW_VERSION_MAJOR, CW_VERSION_MINOR, CW_VERSION_PATCH
      call check_string(cw_version_string(), trim(expected), 'cw_version_string()')
      ! Codes are appended, never renumbered: 0, 1, 2, ... in list order.
      call check_int(CW_STATUS_COUNT, 14, 'number of status codes in CW_STATUS_LIST')
      do k = 1, CW_STATUS_COUNT
         call check_int(int(CW_STATUS_CODES(k)), k - 1, 'status codes are consecutive')
         call check_string(cw_status_string(int(CW_STATUS_CODES(k))), trim(CW_STATUS_MESSAGES(k)), &
                           'cw_status_string matches CW_STATUS_LIST')
      end do
      call check_int(int(CW_OK), 0, 'CW_OK')
      call check_int(int(CW_ERR_INTERNAL), 12, 'CW_ERR_INTERNAL')
      call check_int(int(CW_ERR_NOT_CONVERGED), 13, 'CW_ERR_NOT_CONVERGED')
      call check_string(cw_status_string(-1), 'unknown status code', 'cw_status_string(-1)')
      call check_string(cw_status_string(CW_STATUS_COUNT), 'unknown status code', &
                        'cw_status_string(past the list)')
      call check_int(int(CW_MAX_GRID_CELLS), 1000, 'CW_MAX_GRID_CELLS')
      call check_close(CW_MAX_BOX_SCALE, 100.0_c_double, 0.0_c_double, 0.0_c_double, 'CW_MAX_BOX_SCALE')
      call check_close(CW_MIN_ASPECT, 1e-3_c_double, 0.0_c_double, 0.0_c_double, 'CW_MIN_ASPECT')
      call check_close(CW_MAX_ASPECT, 1e3_c_double, 0.0_c_double, 0.0_c_double, 'CW_MAX_ASPECT')
   end subroutine check_constants

   subroutine check_structs()
      type(cw_grid) :: g
      type(cw_params) :: p
      type(cw_result) :: r
      type(cw_accumulation) :: t
      call cw_grid_init(g)
      call check_true(g%struct_size == c_sizeof(g), 'cw_grid: Fortran size = C sizeof')
      call check_int(int(g%kind), int(CW_GRID_KALKER_STRIPS), 'grid default kind')
      call check_int(int(g%nx), 20, 'grid default nx')
      call check_int(int(g%ny), 20, 'grid default ny')
      call check_close(g%box_scale, 1.0_c_double, 0.0_c_double, 0.0_c_double, 'grid default box_scale')
      call cw_params_init(p)
      call check_true(p%struct_size == c_sizeof(p), 'cw_params: Fortran size = C sizeof')
      call check_close(p%a, 6e-3_c_double, 0.0_c_double, 0.0_c_double, 'params default a')
      call check_close(p%b, 6e-3_c_double, 0.0_c_double, 0.0_c_double, 'params default b')
      call check_close(p%normal_force, 80e3_c_double, 0.0_c_double, 0.0_c_double, 'params default N')
      call check_close(p%mu, 0.3_c_double, 0.0_c_double, 0.0_c_double, 'params default mu')
      call check_int(int(p%flexibility), int(CW_FLEX_FROM_MATERIAL), 'params default flexibility')
      call check_int(int(p%pressure), int(CW_PRESSURE_PARABOLIC), 'params default pressure')
      call check_close(p%G, 82e9_c_double, 0.0_c_double, 0.0_c_double, 'params default G')
      call check_close(p%nu, 0.28_c_double, 0.0_c_double, 0.0_c_double, 'params default nu')
      call check_true(p%L1 == 0 .and. p%L2 == 0 .and. p%L3 == 0, 'params default L1..L3 = 0')
      call check_true(p%xi_x == 0 .and. p%xi_y == 0 .and. p%phi == 0, 'params default creepages 0')
      call check_int(int(p%rolling_direction), 1, 'params default rolling_direction (last field)')
      r%Fx = 5
      call cw_result_init(r)
      call check_true(r%struct_size == c_sizeof(r), 'cw_result: Fortran size = C sizeof')
      call check_true(r%Fx == 0 .and. r%profile_rms_diff == 0, 'cw_result_init zeroes')
      t%steps = 3
      call cw_accumulation_init(t)
      call check_true(t%struct_size == c_sizeof(t), 'cw_accumulation: Fortran size = C sizeof')
      call check_true(t%steps == 0_c_int64_t, 'cw_accumulation_init zeroes')
   end subroutine check_structs

   subroutine contact(p, xi, eta, phi)
      type(cw_params), intent(out) :: p
      real(c_double), intent(in) :: xi, eta, phi
      call cw_params_init(p)
      p%a = 8e-3_c_double
      p%b = 5e-3_c_double
      p%xi_x = xi
      p%xi_y = eta
      p%phi = phi
   end subroutine contact

   subroutine check_solver()
      type(cw_solver_type) :: s, other
      type(cw_params) :: p
      type(cw_result) :: r, r2
      real(c_double) :: map(nx, ny), vec(nx*ny), area(nx, ny), small(5, 5), swapped(ny, nx)
      real(c_double) :: x(nx, ny), y(nx, ny), sx(nx, ny), sy(nx, ny)
      real(c_double) :: py(ny), pw(ny), pp(ny), short(ny - 1)
      integer(c_int) :: state(nx, ny), state_vec(nx*ny)
      integer :: stat, mx, my, j
      character(len=:), allocatable :: msg

      ! Not created yet: every call reports CW_ERR_NULL_POINTER, none stops.
      call contact(p, 1e-3_c_double, -5e-4_c_double, -0.5_c_double)
      call check_true(.not. s%is_created(), 'solver not created initially')
      call s%solve(p, stat=stat, errmsg=msg)
      call check_int(stat, int(CW_ERR_NULL_POINTER), 'solve before create')
      call check_true(index(msg, 'not been created') > 0, 'solve before create: message')
      call check_string(s%last_error(), 'the solver has not been created', 'last_error before create')
      call s%destroy()
      call s%destroy()

      call s%create(nx=0, ny=ny, stat=stat, errmsg=msg)
      call check_int(stat, int(CW_ERR_GRID_OUT_OF_RANGE), 'create with nx = 0')
      call check_true(index(msg, 'nx') > 0, 'create with nx = 0: message names nx')
      call check_true(.not. s%is_created(), 'failed create leaves no solver')

      call s%create(nx=nx, ny=ny, stat=stat)
      call check_int(stat, int(CW_OK), 'create')
      call check_true(s%is_created(), 'is_created after create')
      call s%grid_size(mx, my)
      call check_int(mx, nx, 'grid_size nx')
      call check_int(my, ny, 'grid_size ny')

      map = -7
      call s%get_field(CW_FIELD_PX, map, stat=stat)
      call check_int(stat, int(CW_ERR_NO_SOLUTION), 'get_field before solve')
      call check_true(all(map == -7), 'nothing written on error')

      call s%solve(p, CW_SOLVE_FULL, r, stat=stat)
      call check_int(stat, int(CW_OK), 'solve')
      call check_string(s%last_error(), '', 'last_error after success')
      ! Forces act on the wheel, opposite to the creepages (header "Forces"):
      ! Fx against xi_x; Fy against the lateral creepage and the spin, which
      ! here both ask for a positive Fy (Kalker's linear theory:
      ! Fy = -G c^2 C22 eta - G c^3 C23 phi, tests/data/README.md).
      call check_true(r%Fx < 0 .and. r%Fy > 0, 'force on the wheel opposes the creepage')
      call check_true(r%W_macro > 0, 'W_macro > 0 (dissipation)')
      ! Header: W_consistent = sum of the energy-consistent map = W_macro.
      call check_close(r%W_consistent, r%W_macro, 1e-10_c_double, 0.0_c_double, 'W_consistent = W_macro')
      call check_close(r%K, r%W_macro/r%W_micro_paper, 1e-15_c_double, 0.0_c_double, &
                       'K = W_macro/W_micro_paper (paper eq. 39)')
      call check_int(r%n_contact, nx*ny, 'strip grid: every element in contact')
      call check_int(r%n_adhesion + r%n_slip, r%n_contact, 'adhesion + slip = contact')
      call s%get_result(r2)
      call check_same(r2%Fx, r%Fx, 'get_result Fx')
      call check_same(r2%W_micro_paper, r%W_micro_paper, 'get_result W_micro_paper')

      ! The calibrated model through the same params type: it
      ! solves, says so, and its map sums to W_macro; then back to FASTSIM.
      p%model = CW_MODEL_CALIBRATED
      call s%solve(p, CW_SOLVE_FULL, r2, stat=stat)
      call check_int(stat, int(CW_OK), 'calibrated solve')
      call check_int(r2%model, int(CW_MODEL_CALIBRATED), 'result names the calibrated model')
      call check_true(r2%Fx < 0 .and. r2%Fy > 0, 'calibrated: force opposes the creepage')
      call check_close(r2%W_consistent, r2%W_macro, 1e-10_c_double, 0.0_c_double, &
                       'calibrated: W_consistent = W_macro')
      p%model = CW_MODEL_FASTSIM
      call s%solve(p, CW_SOLVE_FULL, r2, stat=stat)
      call check_same(r2%Fx, r%Fx, 'FASTSIM after calibrated: same Fx')

      ! Layout: i along x (increasing), j along y (increasing).
      call s%get_field(CW_FIELD_X, x)
      call s%get_field(CW_FIELD_Y, y)
      call check_true(all(x(2:, :) > x(:nx - 1, :)), 'x increases with i')
      call check_true(all(y(:, 2:) > y(:, :ny - 1)), 'y increases with j')
      call check_true(all(abs(x) < p%a) .and. all(abs(y) < p%b), 'element centres inside the ellipse')
      call s%get_field(CW_FIELD_AREA, area)
      ! Midpoint rule on 9 strips: within 2 % of the ellipse area pi a b.
      call check_close(sum(area), pi*p%a*p%b, 0.02_c_double, 0.0_c_double, 'sum of element areas')
      call s%get_field(CW_FIELD_PZ, map)
      call check_close(sum(map*area), p%normal_force, 0.03_c_double, 0.0_c_double, 'sum pz dA = N')
      call s%get_field(CW_FIELD_PX, map)
      call check_close(sum(map*area), r%Fx, 1e-12_c_double, 0.0_c_double, 'sum px dA = Fx')
      call s%get_field(CW_FIELD_PY, map)
      call check_close(sum(map*area), r%Fy, 1e-12_c_double, 0.0_c_double, 'sum py dA = Fy')
      call s%get_field(CW_FIELD_MZ, map)
      call check_close(sum(map), r%Mz, 1e-12_c_double, 0.0_c_double, 'sum of moment map = Mz')
      call s%get_field(CW_FIELD_WORK_PAPER, map)
      call check_close(sum(map), r%W_micro_paper, 1e-12_c_double, 0.0_c_double, 'sum of paper map')
      call s%get_field(CW_FIELD_WORK_CONSISTENT, map)
      call check_close(sum(map), r%W_consistent, 1e-12_c_double, 0.0_c_double, 'sum of consistent map')
      call s%get_field(CW_FIELD_WORK_CONSISTENT, vec)
      call check_true(all(vec == reshape(map, [nx*ny])), 'rank-1 field = column-major map')
      call s%get_state(state)
      call s%get_state(state_vec)
      call check_true(all(state_vec == reshape(state, [nx*ny])), 'rank-1 state = map')
      call check_int(count(state == CW_STATE_SLIP), r%n_slip, 'slip elements')
      call check_int(count(state == CW_STATE_ADHESION), r%n_adhesion, 'adhesion elements')
      call s%get_field(CW_FIELD_SX, sx)
      call s%get_field(CW_FIELD_SY, sy)
      call check_true(all(sx == 0 .or. state == CW_STATE_SLIP) .and. &
                      all(sy == 0 .or. state == CW_STATE_SLIP), 'micro-slip is zero in adhesion')
      call check_true(all(map == 0 .or. state == CW_STATE_SLIP), 'consistent work zero in adhesion')

      call s%get_profile(py, pw, pp)
      do j = 1, ny
         call check_same(py(j), y(1, j), 'profile y = strip centre')
      end do
      ! Work per unit width times the strip width (2b/ny) sums to W.
      call check_close(sum(pw)*2*p%b/ny, r%W_consistent, 1e-12_c_double, 0.0_c_double, 'profile area')
      call check_close(sum(pp)*2*p%b/ny, r%W_consistent, 0.02_c_double, 0.0_c_double, &
                       'equal-area parabola (midpoint rule)')
      call s%get_profile(y=py, stat=stat)
      call check_int(stat, int(CW_OK), 'profile with y only')
      call s%get_profile(stat=stat)
      call check_int(stat, int(CW_OK), 'profile with no buffer')
      call s%get_profile(w=short, stat=stat)
      call check_int(stat, int(CW_ERR_BUFFER_TOO_SMALL), 'profile buffer too short')

      ! Shapes are checked: a map must be (nx, ny).
      swapped = -7
      call s%get_field(CW_FIELD_PX, swapped, stat=stat, errmsg=msg)
      call check_int(stat, int(CW_ERR_INVALID_INPUT), 'map of shape (ny, nx)')
      call check_true(index(msg, 'shape') > 0 .and. all(swapped == -7), 'shape error message, no write')
      call s%get_field(CW_FIELD_PX, small, stat=stat)
      call check_int(stat, int(CW_ERR_BUFFER_TOO_SMALL), 'map too small')
      call s%get_field(CW_FIELD_PX, vec(1:nx*ny - 1), stat=stat)
      call check_int(stat, int(CW_ERR_BUFFER_TOO_SMALL), 'vector too short')
      call s%get_field(99, map, stat=stat)
      call check_int(stat, int(CW_ERR_UNKNOWN_OPTION), 'unknown field')

      ! Forces-only solve: work fields need CW_SOLVE_FULL.
      call s%solve(p, CW_SOLVE_FORCES, r2, stat=stat)
      call check_int(stat, int(CW_OK), 'forces-only solve')
      call check_same(r2%Fx, r%Fx, 'forces-only Fx = full Fx')
      call s%get_field(CW_FIELD_WORK_PAPER, map, stat=stat)
      call check_int(stat, int(CW_ERR_NO_WORK), 'work after a forces-only solve')
      call s%solve(p, 7, stat=stat)
      call check_int(stat, int(CW_ERR_UNKNOWN_OPTION), 'unknown mode')

      ! Invalid input: named in the message; the handle then holds no solution.
      p%a = -1
      call s%solve(p, stat=stat, errmsg=msg)
      call check_int(stat, int(CW_ERR_INVALID_INPUT), 'negative a')
      call check_true(index(msg, 'a = ') > 0, 'message names a: '//msg)
      call check_true(len(s%last_error()) > 0, 'last_error after failure')
      call s%get_field(CW_FIELD_PX, map, stat=stat)
      call check_int(stat, int(CW_ERR_NO_SOLUTION), 'no solution after a failed solve')
      p%struct_size = 0
      call s%solve(p, stat=stat)
      call check_int(stat, int(CW_ERR_STRUCT_SIZE), 'params without cw_params_init')

      ! A second solver on the uniform (CONTACT) grid.
      call other%create(nx=nx, ny=ny, kind=CW_GRID_UNIFORM, box_scale=1.2_c_double, stat=stat)
      call check_int(stat, int(CW_OK), 'uniform grid create')
      call contact(p, 1e-3_c_double, 0.0_c_double, 0.0_c_double)
      call other%solve(p, stat=stat)
      call check_int(stat, int(CW_OK), 'uniform grid solve')
      call other%get_state(state)
      call check_true(any(state == CW_STATE_EXTERIOR), 'uniform box has exterior elements')
      call other%destroy()
      call s%destroy()
      call s%destroy()
      call check_true(.not. s%is_created(), 'destroy is idempotent')
      ! An empty solver may be assigned (nothing to share).
      other = s
      call check_true(.not. other%is_created(), 'assigning an empty solver')
   end subroutine check_solver

   subroutine check_accumulator()
      type(cw_solver_type) :: s, s2
      type(cw_accumulator_type) :: acc
      type(cw_params) :: p
      type(cw_result) :: r1, r2
      type(cw_accumulation) :: t
      real(c_double) :: map(nx, ny), paper(nx, ny), strips(ny), vec(nx*ny)
      integer :: stat, j
      character(len=:), allocatable :: msg

      call acc%create(s, stat=stat)
      call check_int(stat, int(CW_ERR_NULL_POINTER), 'accumulator on a missing solver')
      call check_string(acc%last_error(), 'the accumulator has not been created', 'acc last_error')
      call s%create(nx=nx, ny=ny)
      call acc%create(s)
      call check_true(acc%is_created(), 'accumulator created')
      call contact(p, 1e-3_c_double, -5e-4_c_double, 0.5_c_double)
      call s%solve(p, CW_SOLVE_FULL, r1)
      call acc%add(s, 0.25_c_double)
      call contact(p, -2e-3_c_double, 1e-3_c_double, -1.5_c_double)
      call s%solve(p, CW_SOLVE_FULL, r2)
      call acc%add(s, 0.75_c_double)
      call acc%get_totals(t)
      call check_true(t%steps == 2_c_int64_t, 'two steps')
      call check_close(t%distance, 1.0_c_double, 1e-15_c_double, 0.0_c_double, 'distance = sum V dt')
      ! Paper eqs. 35, 37, 39.
      call check_close(t%W_macro, 0.25_c_double*r1%W_macro + 0.75_c_double*r2%W_macro, &
                       1e-14_c_double, 0.0_c_double, 'eq. 35: sum W_macro V dt')
      call check_close(t%W_micro_paper, 0.25_c_double*r1%W_micro_paper + &
                       0.75_c_double*r2%W_micro_paper, 1e-14_c_double, 0.0_c_double, &
                       'eq. 37: sum W_micro V dt')
      call check_close(t%K, t%W_macro/t%W_micro_paper, 1e-15_c_double, 0.0_c_double, 'eq. 39 over the run')
      call acc%get_field(CW_FIELD_WORK_CONSISTENT, map)
      call check_close(sum(map), t%W_macro, 1e-10_c_double, 0.0_c_double, 'accumulated map sums to W_macro')
      call acc%get_field(CW_FIELD_WORK_PAPER, paper)
      call check_close(sum(paper), t%W_micro_paper, 1e-12_c_double, 0.0_c_double, 'accumulated paper map')
      call acc%get_field(CW_FIELD_WORK_PAPER, vec)
      call check_true(all(vec == reshape(paper, [nx*ny])), 'rank-1 accumulated map')
      call acc%get_strip_work(strips)
      do j = 1, ny
         call check_close(strips(j), sum(map(:, j)), 1e-12_c_double, 1e-300_c_double, 'strip work')
      end do

      call acc%add(s, -1.0_c_double, stat=stat, errmsg=msg)
      call check_int(stat, int(CW_ERR_INVALID_INPUT), 'negative distance')
      call check_true(index(msg, 'distance') > 0, 'message names distance')
      call check_true(len(acc%last_error()) > 0, 'accumulator last_error')
      call acc%get_totals(t)
      call check_true(t%steps == 2_c_int64_t, 'failed add changes nothing')
      call s2%create(nx=nx + 1, ny=ny)
      call s2%solve(p)
      call acc%add(s2, 1.0_c_double, stat=stat)
      call check_int(stat, int(CW_ERR_GRID_MISMATCH), 'solver of another grid')
      call acc%get_field(CW_FIELD_PX, map, stat=stat)
      call check_int(stat, int(CW_ERR_UNKNOWN_OPTION), 'accumulated field must be a work map')
      call acc%get_field(CW_FIELD_WORK_PAPER, map(:, 1:ny - 1), stat=stat)
      call check_int(stat, int(CW_ERR_BUFFER_TOO_SMALL), 'accumulated map too small')
      call acc%get_strip_work(strips(1:ny - 1), stat=stat)
      call check_int(stat, int(CW_ERR_BUFFER_TOO_SMALL), 'strip buffer too short')
      call acc%reset()
      call acc%get_totals(t)
      call check_true(t%steps == 0_c_int64_t .and. t%W_macro == 0, 'reset')
      call acc%destroy()
      call acc%destroy()
      call check_true(.not. acc%is_created(), 'accumulator destroy is idempotent')
      call s%solve(p, CW_SOLVE_FORCES)
      call acc%create(s)
      call acc%add(s, 1.0_c_double, stat=stat)
      call check_int(stat, int(CW_ERR_NO_WORK), 'adding a forces-only solve')
      call acc%destroy()
      call s2%destroy()
      call s%destroy()
   end subroutine check_accumulator

   subroutine check_batch()
      integer, parameter :: n = 6
      type(cw_batch_type) :: batch
      type(cw_solver_type) :: s
      type(cw_params) :: p(n)
      type(cw_result) :: results(n), one, short(n - 1)
      integer(c_int) :: statuses(n)
      integer :: k, stat
      character(len=:), allocatable :: msg

      call batch%solve(p, CW_SOLVE_FULL, results, stat=stat)
      call check_int(stat, int(CW_ERR_NULL_POINTER), 'batch not created')
      call check_string(batch%last_error(), 'the batch has not been created', 'batch last_error')
      call batch%create(nx=nx, ny=ny, threads=2)
      call check_true(batch%is_created(), 'batch created')
      call s%create(nx=nx, ny=ny)
      do k = 1, n
         call contact(p(k), 1e-4_c_double*k, -3e-4_c_double + 1e-4_c_double*k, 0.2_c_double*(k - 3))
      end do
      call batch%solve(p, CW_SOLVE_FULL, results, statuses)
      do k = 1, n
         call s%solve(p(k), CW_SOLVE_FULL, one)
         call check_int(int(statuses(k)), int(CW_OK), 'batch status')
         ! Header: results bitwise identical to one-by-one solves.
         call check_same(results(k)%Fx, one%Fx, 'batch Fx')
         call check_same(results(k)%Fy, one%Fy, 'batch Fy')
         call check_same(results(k)%Mz, one%Mz, 'batch Mz')
         call check_same(results(k)%W_consistent, one%W_consistent, 'batch W_consistent')
         call check_same(results(k)%K, one%K, 'batch K')
      end do
      p(3)%mu = -1
      call batch%solve(p, CW_SOLVE_FULL, results, statuses, stat=stat, errmsg=msg)
      call check_int(stat, int(CW_ERR_INVALID_INPUT), 'batch with one bad contact')
      call check_int(int(statuses(3)), int(CW_ERR_INVALID_INPUT), 'its own status')
      call check_int(int(statuses(2)), int(CW_OK), 'the others succeed')
      call check_true(index(msg, 'params[2]') > 0, 'message names the (0-based) index: '//msg)
      call check_true(len(batch%last_error()) > 0, 'batch last_error after failure')
      call batch%solve(p, CW_SOLVE_FULL, short, stat=stat)
      call check_int(stat, int(CW_ERR_BUFFER_TOO_SMALL), 'results shorter than params')
      call batch%destroy()
      call batch%destroy()
      call check_true(.not. batch%is_created(), 'batch destroy is idempotent')
      call s%destroy()
   end subroutine check_batch

   subroutine check_helpers()
      real(c_double) :: c(4), l(3), h(4), tx, ty
      integer :: stat
      character(len=:), allocatable :: msg
      ! Kalker 1990, Table E.3 (tests/data/kalker_cij.csv): a/b = 1, nu = 0.25.
      call cw_kalker_coefficients(1.0_c_double, 0.25_c_double, c)
      call check_close(c(1), 4.12_c_double, 1e-12_c_double, 0.0_c_double, 'C11(1, 0.25)')
      call check_close(c(2), 3.67_c_double, 1e-12_c_double, 0.0_c_double, 'C22(1, 0.25)')
      call check_close(c(3), 1.47_c_double, 1e-12_c_double, 0.0_c_double, 'C23(1, 0.25)')
      call check_close(c(4), 1.19_c_double, 1e-12_c_double, 0.0_c_double, 'C33(1, 0.25)')
      call cw_kalker_coefficients(-1.0_c_double, 0.25_c_double, c, stat=stat, errmsg=msg)
      call check_int(stat, int(CW_ERR_INVALID_INPUT), 'negative a/b')
      call check_true(index(msg, 'a_over_b') > 0, 'message names a_over_b')
      ! Header: L1 = 8a/(3 C11 G), L2 = 8a/(3 C22 G), L3 = pi a sqrt(a/b)/(4 C23 G).
      call cw_kalker_flexibilities(6e-3_c_double, 6e-3_c_double, 82e9_c_double, 0.25_c_double, l)
      call check_close(l(1), 8*6e-3_c_double/(3*4.12_c_double*82e9_c_double), 1e-14_c_double, &
                       0.0_c_double, 'L1')
      call check_close(l(2), 8*6e-3_c_double/(3*3.67_c_double*82e9_c_double), 1e-14_c_double, &
                       0.0_c_double, 'L2')
      call check_close(l(3), pi*6e-3_c_double/(4*1.47_c_double*82e9_c_double), 1e-14_c_double, &
                       0.0_c_double, 'L3')
      call cw_kalker_flexibilities(6e-3_c_double, 6e-3_c_double, -1.0_c_double, 0.25_c_double, l, &
                                   stat=stat)
      call check_int(stat, int(CW_ERR_INVALID_INPUT), 'negative G')
      ! Hertz, equal curvatures: a circle, p0 = 3N/(2 pi a b).
      call cw_hertz_solve(2.0_c_double, 2.0_c_double, 1e5_c_double, 1.1e11_c_double, h)
      call check_close(h(2), h(1), 1e-12_c_double, 0.0_c_double, 'Hertz A = B gives a = b')
      call check_close(h(3), 3*1e5_c_double/(2*pi*h(1)*h(2)), 1e-12_c_double, 0.0_c_double, &
                       'Hertz p0 = 3N/(2 pi a b)')
      call cw_hertz_solve(2.0_c_double, 0.0_c_double, 1e5_c_double, 1.1e11_c_double, h, stat=stat)
      call check_int(stat, int(CW_ERR_INVALID_INPUT), 'Hertz B = 0')
      ! Kalker 1982 check row 4 (see test_fortran_kalker1982 for all of them).
      call cw_fastsim_normalised(1.0_c_double, -2.0_c_double, 2.0_c_double, 4.0_c_double, 5, 5, &
                                 3.0_c_double, tx, ty)
      call check_close(tx, 0.5684_c_double, 0.0_c_double, 0.5e-4_c_double, 'Kalker 1982 TX row 4')
      call cw_fastsim_normalised(1.0_c_double, -2.0_c_double, 2.0_c_double, 4.0_c_double, 0, 5, &
                                 3.0_c_double, tx, ty, stat=stat, errmsg=msg)
      call check_int(stat, int(CW_ERR_GRID_OUT_OF_RANGE), 'normalised FASTSIM mx = 0')
      call check_true(index(msg, 'outside 1..1000') > 0, 'message gives the range: '//msg)
   end subroutine check_helpers

end program test_fortran_api
