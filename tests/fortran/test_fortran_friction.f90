! A friction law of the slip speed through module creepwork: the law's
! fields of the bind(C) mirror of cw_params and cw_result, and
! cw_friction_polach. Expected values:
!   - the same contact through the C ABI (friction_cases.c): Fx and mu_min
!     bit for bit, the law at every element and at the global slip speed;
!   - CONTACT's tractcurv series 4 at 2 % creepage (tests/data/
!     contact_tractcurv.csv: Fx/(mu_s N) = -0.8444, printed to 4 digits; our
!     FASTSIM within half a digit + 6e-5, as test_capi_friction);
!   - cw_friction_polach: mu = A mu0, mu_e1 = (1 - A) mu0, s_h1 = ln2/B;
!   - errors with stat and errmsg naming the input (V, polach_A).
program test_fortran_friction
   use, intrinsic :: iso_c_binding, only: c_double, c_int
   use creepwork
   use cw_test_support
   implicit none

   interface
      function cw_test_friction_c(xi_x, speed, out) bind(C) result(status)
         import :: c_double, c_int
         real(c_double), value :: xi_x
         integer(c_int), value :: speed
         real(c_double), intent(out) :: out(2)
         integer(c_int) :: status
      end function cw_test_friction_c
   end interface

   call same_bits_as_c()
   call polach()
   call errors()
   call test_summary('test_fortran_friction')

contains

   function tractcurv(xi_x, speed) result(p)
      real(c_double), intent(in) :: xi_x
      integer, intent(in) :: speed
      type(cw_params) :: p
      call cw_params_init(p)
      p%a = 6.304e-3_c_double
      p%b = 12.61e-3_c_double
      p%normal_force = 106.7e3_c_double
      p%exact_load = 1
      p%V = 10.0_c_double
      p%xi_x = xi_x
      p%friction_law = CW_FRICTION_EXPONENTIAL
      p%mu = 0.1368_c_double
      p%mu_e1 = 0.2232_c_double
      p%s_h1 = 0.990_c_double
      p%friction_speed = speed
      if (speed == CW_FRICTION_SPEED_GLOBAL) then
         p%k0 = 0.54_c_double
         p%alpha_inf = 0.02_c_double
         p%beta = 0.62_c_double
      end if
   end function tractcurv

   subroutine same_bits_as_c()
      type(cw_solver_type) :: s
      type(cw_result) :: r
      real(c_double) :: c(2)
      real(c_double), parameter :: xis(3) = [0.004_c_double, 0.02_c_double, 0.15_c_double]
      integer :: k, speed, mode
      call s%create(nx=48, ny=44, kind=CW_GRID_UNIFORM, box_scale=1.1_c_double)
      do speed = CW_FRICTION_SPEED_LOCAL, CW_FRICTION_SPEED_GLOBAL
         mode = merge(CW_SOLVE_FULL, CW_SOLVE_FORCES, speed == CW_FRICTION_SPEED_GLOBAL)
         do k = 1, size(xis)
            call s%solve(tractcurv(xis(k), speed), mode, r)
            call check_int(int(cw_test_friction_c(xis(k), speed, c)), 0, 'C solve')
            call check_same(r%Fx, c(1), 'Fx bitwise C''s')
            call check_same(r%mu_min, c(2), 'mu_min bitwise C''s')
            call check_close(r%mu_static, 0.36_c_double, 0.0_c_double, 1e-15_c_double, &
                             'mu_static = mu + mu_e1')
            if (speed == CW_FRICTION_SPEED_GLOBAL .and. k == 2) &
               call check_close(r%Fx/(0.36_c_double*106.7e3_c_double), -0.8444_c_double, &
                                0.0_c_double, 0.5e-4_c_double + 6e-5_c_double, &
                                'tractcurv series 4 at 2 %')
         end do
      end do
      call s%destroy()
   end subroutine same_bits_as_c

   subroutine polach()
      type(cw_params) :: p
      call cw_params_init(p)
      call cw_friction_polach(0.36_c_double, 0.38_c_double, 0.7_c_double, p)
      call check_int(p%friction_law, int(CW_FRICTION_EXPONENTIAL), 'Polach: exponential law')
      call check_close(p%mu, 0.38_c_double*0.36_c_double, 1e-15_c_double, 0.0_c_double, 'mu = A mu0')
      call check_close(p%mu_e1, 0.62_c_double*0.36_c_double, 1e-15_c_double, 0.0_c_double, &
                       'mu_e1 = (1 - A) mu0')
      call check_close(p%s_h1, log(2.0_c_double)/0.7_c_double, 1e-15_c_double, 0.0_c_double, &
                       's_h1 = ln2/B')
   end subroutine polach

   subroutine errors()
      type(cw_solver_type) :: s
      type(cw_params) :: p
      type(cw_result) :: r
      integer :: stat
      character(len=:), allocatable :: msg
      call cw_params_init(p)
      call cw_friction_polach(0.36_c_double, 1.5_c_double, 0.7_c_double, p, stat=stat, errmsg=msg)
      call check_int(stat, int(CW_ERR_INVALID_INPUT), 'Polach A = 1.5')
      call check_true(index(msg, 'polach_A') > 0, 'Polach A = 1.5: message names polach_A')
      call s%create(nx=20, ny=20)
      p = tractcurv(0.01_c_double, CW_FRICTION_SPEED_LOCAL)
      p%V = 0.0_c_double
      call s%solve(p, CW_SOLVE_FORCES, r, stat=stat, errmsg=msg)
      call check_int(stat, int(CW_ERR_INVALID_INPUT), 'a law with V = 0')
      call check_true(index(msg, 'V = 0') > 0, 'V = 0: message names V')
      call s%destroy()
   end subroutine errors

end program test_fortran_friction
