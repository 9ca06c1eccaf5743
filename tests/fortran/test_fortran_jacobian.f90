! The Jacobian through module creepwork and the legacy layer (doc/theory/jacobians.md):
!   module  cw_solver_type%solve_jacobian: jacobian(r, c) = d(Fx, Fy, Mz,
!           W_macro)(r)/d(xi_x, xi_y, phi, N)(c) -- checked against central
!           differences of the module's own solve (step 1e-5 of a
!           characteristic creepage, 1e-6 relative to the row's scale, as
!           test_core_jacobian's step study), so the transposition to
!           Fortran's (row, column) is tested, not assumed; errors through stat
!           leave jacobian untouched
!   legacy  CWJACO equals the module bitwise (same solve); FN = 0 gives
!           IERR = CW_ERR_INVALID_INPUT and writes nothing
program test_fortran_jacobian
   use, intrinsic :: iso_c_binding, only: c_double, c_int
   use creepwork
   use cw_test_support
   implicit none
   include 'creepwork_legacy.fi'

   integer, parameter :: nx = 20, ny = 16
   real(c_double), parameter :: sentinel = -12345.0_c_double
   type(cw_solver_type) :: solver
   type(cw_params) :: p
   type(cw_result) :: r
   real(c_double) :: jac(4, 4), dfj(4, 4), scale(4), row_scale, fd, h
   real(c_double) :: up(4), down(4), fx, fy, fmz, wmac
   integer :: stat, row, col, k
   integer(c_int) :: ierr

   call solver%create(nx=nx, ny=ny)
   call cw_params_init(p)
   p%a = 6e-3_c_double
   p%b = 4.5e-3_c_double
   p%xi_x = 1e-3_c_double
   p%xi_y = -6e-4_c_double
   p%phi = 0.3_c_double
   call solver%solve_jacobian(p, jac, CW_SOLVE_FORCES, r, stat=stat)
   call check_int(stat, CW_OK, 'solve_jacobian')
   call check_true(r%n_slip > 0 .and. r%n_adhesion > 0, 'partial slip')

   scale = [1e-3_c_double, 1e-3_c_double, 1e-3_c_double/sqrt(p%a*p%b), p%normal_force]
   do col = 1, 4
      h = 1e-5_c_double*scale(col)
      call totals(col, h, up)
      call totals(col, -h, down)
      do row = 1, 4
         row_scale = 0
         do k = 1, 4
            row_scale = row_scale + abs(jac(row, k))*scale(k)
         end do
         fd = (up(row) - down(row))/(2*h)
         call check_close(jac(row, col), fd, 0.0_c_double, 1e-6_c_double*row_scale/scale(col), &
                          'jacobian(row, col) vs central difference')
      end do
   end do
   call check_true(jac(1, 1) < 0 .and. jac(2, 2) < 0, 'forces oppose their creepage')

   ! Legacy: Kalker's strips, parabolic, material flexibilities = the module's.
   call CWJACO(p%a, p%b, p%normal_force, p%mu, p%G, p%nu, p%xi_x, p%xi_y, p%phi, nx, ny, &
               fx, fy, fmz, wmac, dfj, ierr)
   call check_int(int(ierr), CW_OK, 'CWJACO')
   call check_same(fx, r%Fx, 'CWJACO FX')
   call check_same(wmac, r%W_macro, 'CWJACO WMAC')
   do col = 1, 4
      do row = 1, 4
         call check_same(dfj(row, col), jac(row, col), 'CWJACO DFJ = module jacobian')
      end do
   end do

   ! Errors write nothing.
   dfj = sentinel
   fx = sentinel
   call CWJACO(p%a, p%b, 0.0_c_double, p%mu, p%G, p%nu, p%xi_x, p%xi_y, p%phi, nx, ny, &
               fx, fy, fmz, wmac, dfj, ierr)
   call check_int(int(ierr), CW_ERR_INVALID_INPUT, 'CWJACO with FN = 0')
   call check_true(all(dfj == sentinel) .and. fx == sentinel, 'CWJACO error writes nothing')
   ! The calibrated model: the same call, its own derivatives (Fx, Fy oppose
   ! their creepages; totals bitwise its plain solve's).
   p%model = CW_MODEL_CALIBRATED
   call solver%solve_jacobian(p, jac, CW_SOLVE_FORCES, r, stat=stat)
   call check_int(stat, CW_OK, 'calibrated solve_jacobian')
   call check_true(jac(1, 1) < 0 .and. jac(2, 2) < 0, 'calibrated: forces oppose creepage')
   call totals(0, 0.0_c_double, up)
   call check_same(up(1), r%Fx, 'calibrated Fx = its plain solve')
   call check_same(up(3), r%Mz, 'calibrated Mz = its plain solve')
   ! Its table needs G and nu: given flexibilities are refused, nothing written.
   jac = sentinel
   p%flexibility = CW_FLEX_GIVEN
   p%L1 = 1e-11_c_double
   p%L2 = 1e-11_c_double
   p%L3 = 1e-11_c_double
   call solver%solve_jacobian(p, jac, stat=stat)
   call check_int(stat, CW_ERR_INVALID_INPUT, 'calibrated model, given flexibilities')
   call check_true(all(jac == sentinel), 'module error writes nothing')
   call check_true(index(solver%last_error(), 'calibrated') > 0, 'message names the model')

   call solver%destroy()
   call test_summary('test_fortran_jacobian')

contains

   ! Fx, Fy, Mz, W_macro with input col moved by dh.
   subroutine totals(col, dh, out)
      integer, intent(in) :: col
      real(c_double), intent(in) :: dh
      real(c_double), intent(out) :: out(4)
      type(cw_params) :: q
      type(cw_result) :: t
      q = p
      select case (col)
      case (1)
         q%xi_x = q%xi_x + dh
      case (2)
         q%xi_y = q%xi_y + dh
      case (3)
         q%phi = q%phi + dh
      case default
         q%normal_force = q%normal_force + dh
      end select
      call solver%solve(q, CW_SOLVE_FORCES, t)
      call check_int(t%n_slip, r%n_slip, 'no element changes state within the step')
      out = [t%Fx, t%Fy, t%Mz, t%W_macro]
   end subroutine totals

end program test_fortran_jacobian
