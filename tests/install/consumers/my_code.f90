! A Fortran program outside the creepwork tree, compiled against an
! installed prefix with the plain line
!   gfortran my_code.f90 -I<prefix>/include/creepwork/fortran -L<prefix>/lib \
!            -lcreepwork_fortran -lcreepwork
! or through find_package(creepwork) (creepwork::fortran). Solves one contact
! and checks the energy balance the header promises (W_consistent = W_macro).
program my_code
   use, intrinsic :: iso_c_binding, only: c_double
   use creepwork
   implicit none
   type(cw_solver_type) :: solver
   type(cw_params) :: p
   type(cw_result) :: r
   real(c_double) :: work(16, 12)
   if (cw_library_version_number() /= CW_VERSION_NUMBER) error stop 'header and library differ'
   call solver%create(nx=16, ny=12)
   call cw_params_init(p)
   p%xi_x = 1e-3_c_double
   p%phi = 0.5_c_double
   call solver%solve(p, CW_SOLVE_FULL, r)
   call solver%get_field(CW_FIELD_WORK_CONSISTENT, work)
   call solver%destroy()
   print '(a,a,a,es12.4,a,es12.4)', 'creepwork ', cw_version_string(), ': Fx =', r%Fx, &
      ' N, W_macro =', r%W_macro
   if (abs(sum(work) - r%W_macro) > 1e-10_c_double*abs(r%W_macro)) error stop 'work map'
end program my_code
