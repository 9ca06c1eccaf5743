! CWFLAW, the legacy layer's friction law of the slip speed:
!   module       equals module creepwork's solve of the same contact (CWSOLX's
!                grid, the law in cw_params), bitwise, for the exact model
!                and FASTSIM
!   sliding      at 20 % creepage every element slides at about xi V, so
!                FX = -mu(xi V) FN (the closed form of sliding friction; the
!                elastic part of the slip lowers the elements' mean slip
!                speed a little: +2.8e-4 exact, +7.5e-4 FASTSIM measured on
!                this grid, 1.5e-3 asserted; twice V would be 26 % off), and
!                the coefficient at rest is FMU + FE1
!   errors       V = 0 with a law and LAW = 1 fail naming the input, the
!                outputs untouched
program test_fortran_legacy_friction
   use, intrinsic :: iso_c_binding, only: c_double, c_int
   use creepwork
   use cw_test_support
   implicit none
   include 'creepwork_legacy.fi'

   integer(c_int), parameter :: nx = 24, ny = 24
   real(c_double), parameter :: a = 6e-3_c_double, b = 4e-3_c_double, fn = 60e3_c_double
   real(c_double), parameter :: box = 1.2_c_double, v = 10.0_c_double
   ! CONTACT's tractcurv law: FKIN 0.14, FEXP1 0.19, SABSH1 1.25 m/s
   real(c_double), parameter :: fkin = 0.14_c_double, fe1 = 0.19_c_double, sh1 = 1.25_c_double

   call check_module(int(CW_MODEL_EXACT, c_int))
   call check_module(int(CW_MODEL_FASTSIM, c_int))
   call check_sliding(int(CW_MODEL_EXACT, c_int))
   call check_sliding(int(CW_MODEL_FASTSIM, c_int))
   call check_errors()
   call test_summary('test_fortran_legacy_friction')

contains

   subroutine check_module(model)
      integer(c_int), intent(in) :: model
      type(cw_solver_type) :: solver
      type(cw_params) :: p
      type(cw_result) :: r
      real(c_double) :: fx, fy, fmz, fmur(3)
      integer(c_int) :: ierr
      call CWFLAW(model, a, b, fn, fkin, 82e9_c_double, 0.28_c_double, 2e-3_c_double, &
                  -1e-3_c_double, 1.5_c_double, nx, ny, box, int(CW_FRICTION_EXPONENTIAL, c_int), &
                  fe1, sh1, 0.0_c_double, 0.0_c_double, v, fx, fy, fmz, fmur, ierr)
      call check_int(int(ierr), CW_OK, 'CWFLAW')
      call cw_params_init(p)
      p%a = a
      p%b = b
      p%normal_force = fn
      p%mu = fkin
      p%G = 82e9_c_double
      p%nu = 0.28_c_double
      p%xi_x = 2e-3_c_double
      p%xi_y = -1e-3_c_double
      p%phi = 1.5_c_double
      p%model = model
      p%friction_law = CW_FRICTION_EXPONENTIAL
      p%mu_e1 = fe1
      p%s_h1 = sh1
      p%V = v
      call solver%create(nx=int(nx), ny=int(ny), kind=int(CW_GRID_UNIFORM), box_scale=box)
      call solver%solve(p, CW_SOLVE_FORCES, r)
      call check_same(fx, r%Fx, 'CWFLAW FX = module')
      call check_same(fy, r%Fy, 'CWFLAW FY = module')
      call check_same(fmz, r%Mz, 'CWFLAW FMZ = module')
      call check_same(fmur(2), r%mu_min, 'CWFLAW mu_min = module')
      call check_same(fmur(3), r%mu_max, 'CWFLAW mu_max = module')
      call solver%destroy()
   end subroutine check_module

   subroutine check_sliding(model)
      integer(c_int), intent(in) :: model
      real(c_double) :: fx, fy, fmz, fmur(3), mu
      integer(c_int) :: ierr
      call CWFLAW(model, a, b, fn, fkin, 82e9_c_double, 0.28_c_double, 0.2_c_double, 0.0_c_double, &
                  0.0_c_double, nx, ny, box, int(CW_FRICTION_EXPONENTIAL, c_int), fe1, sh1, &
                  0.0_c_double, 0.0_c_double, v, fx, fy, fmz, fmur, ierr)
      call check_int(int(ierr), CW_OK, 'CWFLAW in full sliding')
      mu = fkin + fe1 * exp(-log(2.0_c_double) * 0.2_c_double * v / sh1)
      call check_close(-fx / fn, mu, 1.5e-3_c_double, 0.0_c_double, 'FX = -mu(xi V) FN in full sliding')
      call check_close(fy, 0.0_c_double, 0.0_c_double, 1e-9_c_double * fn, 'FY = 0 without lateral creepage')
      call check_same(fmur(1), fkin + fe1, 'FMUR(1) = FMU + FE1')
   end subroutine check_sliding

   subroutine check_errors()
      real(c_double) :: fx, fy, fmz, fmur(3)
      integer(c_int) :: ierr
      character(len=200) :: msg
      fx = -7.0_c_double
      call CWFLAW(1_c_int, a, b, fn, fkin, 82e9_c_double, 0.28_c_double, 2e-3_c_double, &
                  0.0_c_double, 0.0_c_double, nx, ny, box, int(CW_FRICTION_EXPONENTIAL, c_int), fe1, &
                  sh1, 0.0_c_double, 0.0_c_double, 0.0_c_double, fx, fy, fmz, fmur, ierr)
      call check_int(int(ierr), CW_ERR_INVALID_INPUT, 'V = 0 with a law: status')
      call check_same(fx, -7.0_c_double, 'V = 0 with a law: FX untouched')
      call CWLAST(msg)
      call check_true(index(msg, 'V') > 0, 'V = 0 with a law: the message names V: '//trim(msg))
      call CWFLAW(1_c_int, a, b, fn, fkin, 82e9_c_double, 0.28_c_double, 2e-3_c_double, &
                  0.0_c_double, 0.0_c_double, nx, ny, box, 1_c_int, fe1, sh1, 0.0_c_double, &
                  0.0_c_double, v, fx, fy, fmz, fmur, ierr)
      call check_int(int(ierr), CW_ERR_UNKNOWN_OPTION, 'LAW = 1: status')
      call CWLAST(msg)
      call check_true(index(msg, 'friction_law') > 0, 'LAW = 1: the message names friction_law: '// &
                      trim(msg))
   end subroutine check_errors

end program test_fortran_legacy_friction
