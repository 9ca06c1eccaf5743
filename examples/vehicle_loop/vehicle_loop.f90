! Vehicle loop, Fortran 2003 version (module creepwork): a wheel on tangent
! track while the wheelset hunts. Same loop as vehicle_loop.c: one solver and
! one accumulator, made once; every step computes the creepages, solves the
! contact and adds the step's work (V*dt of rolling, paper eqs. 35, 37); at
! the end the lateral work profile (accumulated energy-consistent work per
! unit width, J/m) is written.
program vehicle_loop
   use, intrinsic :: iso_c_binding, only: c_double
   use creepwork
   implicit none
   integer, parameter :: nx = 20, ny = 20, steps = 3000
   real(c_double), parameter :: pi = 3.14159265358979323846_c_double
   ! V = 30 m/s, dt = 1 ms; hunting at 2 Hz, 3 mm; conicity 0.15, r0 = 0.46 m.
   real(c_double), parameter :: v = 30, dt = 1e-3_c_double, f = 2, y0 = 3e-3_c_double
   real(c_double), parameter :: lambda = 0.15_c_double, r0 = 0.46_c_double
   real(c_double), parameter :: omega = 2*pi*f
   type(cw_solver_type) :: solver
   type(cw_accumulator_type) :: acc
   type(cw_params) :: p
   type(cw_accumulation) :: totals
   real(c_double) :: t, y, ydot, yaw, ys(ny), strip(ny), width
   integer :: k, j

   call solver%create(nx=nx, ny=ny)
   call acc%create(solver)
   call cw_params_init(p)
   p%a = 6e-3_c_double
   p%b = 4e-3_c_double
   p%normal_force = 60e3_c_double
   p%mu = 0.35_c_double
   do k = 1, steps
      t = k*dt
      y = y0*sin(omega*t)
      ydot = y0*omega*cos(omega*t)
      yaw = 0.7_c_double*ydot/v
      p%xi_x = -lambda*y/r0
      p%xi_y = ydot/v - yaw
      p%phi = (0.05_c_double + 10*y)/r0
      call solver%solve(p, CW_SOLVE_FULL)
      call acc%add(solver, v*dt)
   end do

   call acc%get_totals(totals)
   call acc%get_strip_work(strip)
   call solver%get_profile(y=ys)
   write (*, '(a,i0,a,f0.1,a)') '# creepwork vehicle loop: ', steps, ' steps, ', &
      totals%distance, ' m rolled'
   write (*, '(a,es16.9,a,es16.9,a,f12.9)') '# W_macro = ', totals%W_macro, ' J, W_micro = ', &
      totals%W_micro_paper, ' J, K = ', totals%K
   write (*, '(a)') '# strip  y [m]  work per unit width [J/m]'
   width = 2*p%b/ny
   do j = 1, ny
      write (*, '(i3,1x,es12.5,1x,es16.9)') j, ys(j), strip(j)/width
   end do
   call acc%destroy()
   call solver%destroy()
end program vehicle_loop
