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
! CWFMEM, the same with friction memory and an interface layer:
!   module       equals module creepwork's solve with cw_params' memory and
!                layer fields, bitwise: the exact model with CONTACT's
!                tractcurv layer (GG3 8200 N/mm^2, LAYTHK 1.25 mm) and memory
!                (0.3 mm, 1 mm/s), FASTSIM with the memory; with the memory
!                and layer inputs 0 it is CWFLAW, bitwise
!   errors       a NaN DC names memory_distance (the library's name), a
!                subnormal DC names DC (the legacy layer's check), a negative
!                S0 memory_s0, HL > 0 without G3 layer_G, a layer with FASTSIM
!                layer_h; outputs untouched
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
   call check_memory_module(int(CW_MODEL_EXACT, c_int), 1.25e-3_c_double, 8.2e9_c_double)
   call check_memory_module(int(CW_MODEL_FASTSIM, c_int), 0.0_c_double, 0.0_c_double)
   call check_memory_zero_is_cwflaw()
   call check_memory_errors()
   call test_summary('test_fortran_legacy_friction')

contains

   ! The contact CWFLAW and CWFMEM are called with, as module creepwork's
   ! cw_params: tractcurv's exponential law at V, creepages (2e-3, -1e-3, 1.5).
   function law_params(model) result(p)
      integer(c_int), intent(in) :: model
      type(cw_params) :: p
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
   end function law_params

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
      p = law_params(model)
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

   ! CWFMEM against module creepwork with the memory (and layer h, g3).
   subroutine check_memory_module(model, h, g3)
      integer(c_int), intent(in) :: model
      real(c_double), intent(in) :: h, g3
      type(cw_solver_type) :: solver
      type(cw_params) :: p
      type(cw_result) :: r, plain
      real(c_double) :: fx, fy, fmz, fmur(3)
      integer(c_int) :: ierr
      call CWFMEM(model, a, b, fn, fkin, 82e9_c_double, 0.28_c_double, 2e-3_c_double, &
                  -1e-3_c_double, 1.5_c_double, nx, ny, box, int(CW_FRICTION_EXPONENTIAL, c_int), &
                  fe1, sh1, 0.0_c_double, 0.0_c_double, v, 3e-4_c_double, 1e-3_c_double, h, g3, &
                  0.0_c_double, 0.0_c_double, fx, fy, fmz, fmur, ierr)
      call check_int(int(ierr), CW_OK, 'CWFMEM')
      p = law_params(model)
      call solver%create(nx=int(nx), ny=int(ny), kind=int(CW_GRID_UNIFORM), box_scale=box)
      p%memory_distance = 3e-4_c_double
      p%memory_s0 = 1e-3_c_double
      p%layer_h = h
      p%layer_G = g3
      call solver%solve(p, CW_SOLVE_FORCES, r) ! first: CWFMEM's solver starts cold
      p%memory_distance = 0.0_c_double
      p%layer_h = 0.0_c_double
      p%layer_G = 0.0_c_double
      call solver%solve(p, CW_SOLVE_FORCES, plain)
      call check_same(fx, r%Fx, 'CWFMEM FX = module')
      call check_same(fy, r%Fy, 'CWFMEM FY = module')
      call check_same(fmz, r%Mz, 'CWFMEM FMZ = module')
      call check_same(fmur(2), r%mu_min, 'CWFMEM mu_min = module')
      call check_same(fmur(3), r%mu_max, 'CWFMEM mu_max = module')
      ! the memory and the layer reached the solve
      call check_true(abs(fx - plain%Fx) > 1e-3_c_double * fkin * fn, 'CWFMEM: memory moves FX')
      call solver%destroy()
   end subroutine check_memory_module

   subroutine check_memory_zero_is_cwflaw()
      real(c_double) :: fx, fy, fmz, fmur(3), gx, gy, gmz, gmur(3)
      integer(c_int) :: ierr
      call CWFLAW(1_c_int, a, b, fn, fkin, 82e9_c_double, 0.28_c_double, 2e-3_c_double, &
                  -1e-3_c_double, 1.5_c_double, nx, ny, box, int(CW_FRICTION_EXPONENTIAL, c_int), &
                  fe1, sh1, 0.0_c_double, 0.0_c_double, v, fx, fy, fmz, fmur, ierr)
      call check_int(int(ierr), CW_OK, 'CWFLAW')
      call CWFMEM(1_c_int, a, b, fn, fkin, 82e9_c_double, 0.28_c_double, 2e-3_c_double, &
                  -1e-3_c_double, 1.5_c_double, nx, ny, box, int(CW_FRICTION_EXPONENTIAL, c_int), &
                  fe1, sh1, 0.0_c_double, 0.0_c_double, v, 0.0_c_double, 0.0_c_double, 0.0_c_double, &
                  0.0_c_double, 0.0_c_double, 0.0_c_double, gx, gy, gmz, gmur, ierr)
      call check_int(int(ierr), CW_OK, 'CWFMEM without memory and layer')
      call check_same(gx, fx, 'CWFMEM FX = CWFLAW FX')
      call check_same(gy, fy, 'CWFMEM FY = CWFLAW FY')
      call check_same(gmz, fmz, 'CWFMEM FMZ = CWFLAW FMZ')
      call check_same(gmur(3), fmur(3), 'CWFMEM mu_max = CWFLAW mu_max')
   end subroutine check_memory_zero_is_cwflaw

   ! CWFMEM with one bad input (dc, s0, h, g3 and the model): IERR, FX
   ! untouched, and the message names `name'.
   subroutine memory_refused(model, dc, s0, h, g3, name)
      integer(c_int), intent(in) :: model
      real(c_double), intent(in) :: dc, s0, h, g3
      character(len=*), intent(in) :: name
      real(c_double) :: fx, fy, fmz, fmur(3)
      integer(c_int) :: ierr
      character(len=200) :: msg
      fx = -7.0_c_double
      call CWFMEM(model, a, b, fn, fkin, 82e9_c_double, 0.28_c_double, 2e-3_c_double, 0.0_c_double, &
                  0.0_c_double, nx, ny, box, int(CW_FRICTION_EXPONENTIAL, c_int), fe1, sh1, &
                  0.0_c_double, 0.0_c_double, v, dc, s0, h, g3, 0.0_c_double, 0.0_c_double, fx, fy, &
                  fmz, fmur, ierr)
      call check_int(int(ierr), CW_ERR_INVALID_INPUT, name//': status')
      call check_same(fx, -7.0_c_double, name//': FX untouched')
      call CWLAST(msg)
      call check_true(index(msg, name) > 0, name//': the message names it: '//trim(msg))
   end subroutine memory_refused

   subroutine check_memory_errors()
      use, intrinsic :: ieee_arithmetic, only: ieee_value, ieee_quiet_nan
      real(c_double) :: nan
      nan = ieee_value(0.0_c_double, ieee_quiet_nan)
      call memory_refused(1_c_int, nan, 0.0_c_double, 0.0_c_double, 0.0_c_double, 'memory_distance')
      call memory_refused(1_c_int, 1e-310_c_double, 0.0_c_double, 0.0_c_double, 0.0_c_double, 'DC')
      call memory_refused(1_c_int, 3e-4_c_double, -1.0_c_double, 0.0_c_double, 0.0_c_double, &
                          'memory_s0')
      call memory_refused(1_c_int, 0.0_c_double, 0.0_c_double, 1.25e-3_c_double, 0.0_c_double, &
                          'layer_G')
      call memory_refused(int(CW_MODEL_FASTSIM, c_int), 0.0_c_double, 0.0_c_double, 1.25e-3_c_double, &
                          8.2e9_c_double, 'layer_h')
   end subroutine check_memory_errors

end program test_fortran_legacy_friction
