! The policy every door shares, through module creepwork: cw_params_check
! on one and on many contacts (the input named, its value, how many), the
! placeholders of cw_params_init reported, a gap grid in millimetres;
! cw_grid_init_model (CONTACT's 24 x 24 over 1.2 a x 1.2 b for the exact
! model); cw_input_name; and cw_wheelrail_type%check on the measured MiniProf
! wheel whose flange tip rides on the rail crown (the directory of the
! profiles is the first argument).
program test_fortran_checks
   use, intrinsic :: iso_c_binding, only: c_double, c_loc
   use creepwork
   use cw_test_support
   implicit none

   type(cw_grid) :: g
   type(cw_params) :: p, many(3)
   type(cw_check), allocatable :: checks(:)
   real(c_double), allocatable, target :: h(:, :)
   type(cw_wheelrail_type) :: w
   type(cw_wheelrail_params) :: wp
   type(cw_wheelrail_motion) :: m
   type(cw_wheelrail_totals) :: t
   character(len=1024) :: dir
   integer :: i, j, stat

   call cw_grid_init(g)
   call cw_params_init(p)
   ! placeholders: a, b and N never set
   call cw_params_check(g, [p], checks)
   call check_int(size(checks), 1, 'placeholders: one finding')
   call check_int(int(checks(1)%rule), CW_CHECK_DEFAULT_GEOMETRY, 'placeholders: the rule')
   call check_true(index(cw_check_text(checks(1)%reason), 'left out') > 0, 'placeholders: why')
   ! a = 7.2 m, typed in mm as m (0.1 m is the rule's bound)
   p%a = 7.2_c_double
   p%b = 5e-3_c_double
   p%normal_force = 1e5_c_double
   call cw_params_check(g, [p], checks, stat=stat)
   call check_int(stat, CW_OK, 'stat')
   call check_int(size(checks), 1, 'a in mm: one finding')
   call check_string(cw_check_text(checks(1)%input), 'a', 'a in mm: the input')
   call check_string(cw_check_text(checks(1)%unit), 'm', 'a in mm: the unit')
   call check_close(checks(1)%value, 7.2_c_double, 0.0_c_double, 0.0_c_double, 'a in mm: the value')
   call check_string(cw_check_text(checks(1)%message), 'a = 7.2 m is implausible for a wheel-rail '// &
                     'contact: semi-axes are 1-20 mm (were millimetres typed as metres?)', 'a in mm: message')
   ! three contacts, two with mu = 5
   many = p
   many%a = 7e-3_c_double
   many(2)%mu = 5.0_c_double
   many(3)%mu = 6.0_c_double
   call cw_params_check(g, many, checks)
   call check_int(size(checks), 1, 'many: one rule')
   call check_int(int(checks(1)%contacts), 2, 'many: two contacts')
   call check_int(int(checks(1)%first), 1, 'many: the first (from 0)')
   ! a gap grid in millimetres: its spacing and its heights
   g%kind = CW_GRID_GAP
   g%nx = 10
   g%ny = 8
   g%dx = 0.4_c_double
   g%dy = 0.4_c_double
   allocate (h(10, 8))
   do j = 1, 8
      do i = 1, 10
         h(i, j) = ((i - 5.5_c_double)**2/0.9_c_double + (j - 4.5_c_double)**2/0.5_c_double)*0.16_c_double
      end do
   end do
   p%gap = c_loc(h)
   p%gap_len = size(h)
   call cw_params_check(g, [p], checks)
   call check_int(size(checks), 3, 'gap in mm: dx, dy, heights')
   call check_string(cw_check_text(checks(3)%input), 'gap', 'gap in mm: the heights')
   call check_close(checks(3)%value, maxval(h) - minval(h), 0.0_c_double, 0.5e-6_c_double, 'gap spread')
   ! the exact model's default grid; names
   call cw_grid_init_model(g, CW_MODEL_EXACT)
   call check_int(int(g%kind), CW_GRID_UNIFORM, 'exact grid: uniform')
   call check_int(int(g%nx), 24, 'exact grid: nx')
   call check_close(g%box_scale, 1.2_c_double, 0.0_c_double, 0.0_c_double, 'exact grid: box')
   call cw_grid_init_model(g, 9, stat=stat)
   call check_int(stat, CW_ERR_UNKNOWN_OPTION, 'unknown model')
   call check_string(cw_input_name('N'), 'normal_force', 'N')
   call check_string(cw_input_name('Semi-Hertz'), 'semi_hertz', 'semi-hertz')
   call check_string(cw_input_name('fast'), 'fastsim', 'fast')
   call check_string(cw_input_name('G'), 'G', 'G unchanged')

   ! the MiniProf wheel measured from its flange back, placed as if its
   ! origin were on the tread: found before and after the solve
   call get_command_argument(1, dir)
   call cw_wheelrail_params_init(wp)
   wp%model = CW_MODEL_FASTSIM
   wp%normal_method = CW_NORMAL_SEMI_HERTZ
   call w%create(trim(dir)//'/MBench_UIC60_v3.prr', trim(dir)//'/right-wheel-v1-pre-dry.whl', wp)
   call w%check(checks)
   call check_int(size(checks), 1, 'wheel: the profile')
   call check_int(int(checks(1)%rule), CW_CHECK_PROFILE_ORIGIN, 'wheel: its origin')
   call cw_wheelrail_motion_init(m)
   m%y = 2e-3_c_double
   m%vs = 1.0_c_double
   m%vpitch = -1.0_c_double/0.46_c_double
   call w%solve(m, t, Fz=80e3_c_double)
   call w%check(checks)
   call check_int(size(checks), 2, 'wheel solved: the profile and the flange tip')
   call check_int(int(checks(2)%rule), CW_CHECK_FLANGE_TIP, 'wheel solved: the flange tip')
   call check_close(checks(2)%value, t%z, 0.0_c_double, 1e-5_c_double, 'wheel solved: z')
   call w%destroy()
   wp%wheel_y_offset = wp%flange_back_position
   call w%create(trim(dir)//'/MBench_UIC60_v3.prr', trim(dir)//'/right-wheel-v1-pre-dry.whl', wp)
   call w%solve(m, t, Fz=80e3_c_double)
   call w%check(checks)
   call check_int(size(checks), 0, 'wheel offset: nothing found')
   call w%destroy()
   deallocate (checks) ! the main program's arrays are not freed at its end
   call test_summary('test_fortran_checks')
end program test_fortran_checks
