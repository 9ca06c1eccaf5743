! creepwork quickstart in Fortran: forces and work map of one contact.
program contact_patch
   use, intrinsic :: iso_c_binding, only: c_double
   use creepwork
   implicit none
   integer, parameter :: nx = 40, ny = 30
   type(cw_solver_type) :: solver
   type(cw_params) :: p
   type(cw_result) :: r
   real(c_double) :: work(nx, ny)   ! energy-consistent work map [J/m], (i: x, j: y)

   call solver%create(nx=nx, ny=ny) ! Kalker strip grid; all memory allocated here
   call cw_params_init(p)           ! steel, mu = 0.3, a = b = 6 mm, N = 80 kN
   p%a = 7.5e-3_c_double            ! semi-axes [m]
   p%b = 5.0e-3_c_double
   p%xi_x = 1.0e-3_c_double         ! longitudinal creepage [-]
   p%xi_y = -5.0e-4_c_double        ! lateral creepage [-]
   p%phi = 0.4_c_double             ! spin [1/m]
   call solver%solve(p, CW_SOLVE_FULL, r) ! no stat=: an error stops with its message
   call solver%get_field(CW_FIELD_WORK_CONSISTENT, work) ! filled in place, no copy
   print '(a,3es12.4)', 'Fx, Fy [N], Mz [N m] on the wheel:', r%Fx, r%Fy, r%Mz
   print '(a,es12.4,a,f6.3)', 'W_macro [J/m]:', r%W_macro, '   K:', r%K
   print '(a,es12.4)', 'sum of the work map [J/m]:', sum(work)
   call solver%destroy()            ! explicit and idempotent
end program contact_patch
