! A contact of any shape through module creepwork: a gap grid (CW_GRID_GAP)
! and the gap passed as p%gap = c_loc(h). Expected values:
!   - a Hertzian gap A x^2 + B y^2 on the uniform grid over 1.2 a x 1.2 b,
!     a and b from Hertz's theory (cw_hertz_solve), is the discrete problem
!     the elliptic exact model solves on that grid (header, CW_GRID_GAP): at
!     tolerance 1e-12 both agree to 1e-8 mu N (the C tests find 1e-11);
!   - two separate lobes are two patches whose normal and creep forces add
!     up to the result's (header, cw_solver_get_patches: to rounding);
!   - get_patches without an array gives the count; a gap on a grid that is
!     not a gap grid is refused naming gap;
!   - the Jacobian on the Hertzian gap: its creepage columns are the elliptic
!     exact model's (the same discrete problem and derivative: 1e-8 of the
!     row's scale; the C++ tests find 1e-11), its N column (d/dN with the gap
!     held, where the elliptic model holds a and b) the central difference of
!     the module's own gap solves at step 1e-6 N (1e-6 of the row's scale),
!     so Fortran's (row, column) order is checked; normal_force = 0 is
!     refused through stat naming it, jacobian untouched.
program test_fortran_gap
   use, intrinsic :: iso_c_binding, only: c_double, c_loc, c_size_t
   use creepwork
   use cw_test_support
   implicit none

   real(c_double), parameter :: load = 60e3_c_double, mu = 0.3_c_double

   call hertzian_gap()
   call two_lobes()
   call hertzian_gap_jacobian()
   call test_summary('test_fortran_gap')

contains

   function creep() result(p)
      type(cw_params) :: p
      call cw_params_init(p)
      p%model = CW_MODEL_EXACT
      p%normal_force = load
      p%mu = mu
      p%xi_x = 4e-4_c_double
      p%xi_y = -3e-4_c_double
      p%phi = 0.3_c_double
      p%tolerance = 1e-12_c_double
      p%warm_start = 0
   end function creep

   function gap_grid(nx, ny, x0, y0, dx, dy) result(g)
      integer, intent(in) :: nx, ny
      real(c_double), intent(in) :: x0, y0, dx, dy
      type(cw_grid) :: g
      call cw_grid_init(g)
      g%kind = CW_GRID_GAP
      g%nx = nx
      g%ny = ny
      g%x0 = x0
      g%y0 = y0
      g%dx = dx
      g%dy = dy
   end function gap_grid

   ! The Hertzian gap A x^2 + B y^2 of the ellipse Hertz gives for the
   ! curvatures A, B under the load, on the cell centres of the elliptic
   ! exact model's uniform n x n grid of box scale S; hz: Hertz's a, b, ...
   subroutine hertz_gap(n, S, A, B, hz, g, h)
      integer, intent(in) :: n
      real(c_double), intent(in) :: S, A, B
      real(c_double), intent(out) :: hz(4), h(n, n)
      type(cw_grid), intent(out) :: g
      real(c_double) :: x, y
      integer :: i, j
      call cw_hertz_solve(A, B, load, 82e9_c_double/(1 - 0.28_c_double), hz)
      g = gap_grid(n, n, -S*hz(1) + S*hz(1)/n, -S*hz(2) + S*hz(2)/n, 2*S*hz(1)/n, 2*S*hz(2)/n)
      do j = 1, n
         do i = 1, n
            x = g%x0 + (i - 1)*g%dx
            y = g%y0 + (j - 1)*g%dy
            h(i, j) = A*x**2 + B*y**2
         end do
      end do
   end subroutine hertz_gap

   subroutine hertzian_gap()
      integer, parameter :: n = 24
      real(c_double), parameter :: S = 1.2_c_double
      real(c_double), parameter :: A = 1/(2*0.46_c_double), B = 1/(2*0.30_c_double)
      real(c_double), target :: h(n, n)
      real(c_double) :: hz(4)
      type(cw_grid) :: g
      type(cw_solver_type) :: gap, elliptic
      type(cw_params) :: p
      type(cw_result) :: rg, re
      call hertz_gap(n, S, A, B, hz, g, h)
      call gap%create(grid=g)
      p = creep()
      p%gap = c_loc(h)
      p%gap_len = size(h, kind=c_size_t)
      call gap%solve(p, CW_SOLVE_FULL, rg)
      call elliptic%create(nx=n, ny=n, kind=CW_GRID_UNIFORM, box_scale=S)
      p = creep()
      p%a = hz(1)
      p%b = hz(2)
      call elliptic%solve(p, CW_SOLVE_FULL, re)
      call check_close(rg%Fx, re%Fx, 0.0_c_double, 1e-8_c_double*mu*load, 'Hertzian gap: Fx')
      call check_close(rg%Fy, re%Fy, 0.0_c_double, 1e-8_c_double*mu*load, 'Hertzian gap: Fy')
      call check_close(rg%Mz, re%Mz, 0.0_c_double, 1e-8_c_double*mu*load*hz(1), 'Hertzian gap: Mz')
      call check_int(rg%n_contact, re%n_contact, 'Hertzian gap: n_contact')
      call check_int(rg%n_slip, re%n_slip, 'Hertzian gap: n_slip')
      call check_close(rg%normal_force, load, 1e-12_c_double, 0.0_c_double, 'Hertzian gap: Fn')
      call gap%destroy()
      call elliptic%destroy()
   end subroutine hertzian_gap

   subroutine two_lobes()
      integer, parameter :: nx = 30, ny = 56
      real(c_double), target :: h(nx, ny)
      real(c_double) :: x, y
      type(cw_grid) :: g
      type(cw_solver_type) :: s, plain
      type(cw_params) :: p
      type(cw_result) :: r
      type(cw_patch), allocatable :: patches(:)
      integer :: i, j, count, stat
      character(len=:), allocatable :: message
      g = gap_grid(nx, ny, -5e-3_c_double, -12e-3_c_double, 0.35e-3_c_double, 0.45e-3_c_double)
      do j = 1, ny
         do i = 1, nx
            x = g%x0 + (i - 1)*g%dx
            y = g%y0 + (j - 1)*g%dy
            h(i, j) = min(x**2/0.9_c_double + (y + 6e-3_c_double)**2/0.5_c_double, &
                          x**2/0.9_c_double + (y - 6e-3_c_double)**2/0.5_c_double + 2e-6_c_double)
         end do
      end do
      call s%create(grid=g)
      p = creep()
      p%gap = c_loc(h)
      p%gap_len = size(h, kind=c_size_t)
      call s%solve(p, CW_SOLVE_FULL, r)
      call s%get_patches(count)
      call check_int(count, 2, 'two lobes: the count alone')
      call check_int(r%n_patches, 2, 'two lobes: n_patches')
      allocate (patches(count))
      call s%get_patches(count, patches)
      call check_true(patches(1)%y_centroid < 0 .and. patches(2)%y_centroid > 0, &
                      'two lobes: the lower patch first')
      call check_close(sum(patches%Fn), load, 1e-9_c_double, 0.0_c_double, 'two lobes: sum Fn = N')
      call check_close(sum(patches%Fx), r%Fx, 0.0_c_double, 1e-9_c_double*mu*load, 'two lobes: sum Fx')
      call check_close(sum(patches%Fy), r%Fy, 0.0_c_double, 1e-9_c_double*mu*load, 'two lobes: sum Fy')
      call check_int(sum(patches%n_contact), r%n_contact, 'two lobes: sum n_contact')
      call s%destroy()
      ! A gap on Kalker's strips: refused, naming gap.
      call plain%create()
      p%a = 7e-3_c_double
      p%b = 5e-3_c_double
      p%model = CW_MODEL_FASTSIM
      call plain%solve(p, CW_SOLVE_FORCES, r, stat=stat, errmsg=message)
      call check_int(stat, CW_ERR_INVALID_INPUT, 'gap off a gap grid: status')
      call check_true(index(message, 'gap') > 0, 'gap off a gap grid: the message names gap')
      call plain%destroy()
   end subroutine two_lobes

   subroutine hertzian_gap_jacobian()
      integer, parameter :: n = 24
      real(c_double), parameter :: S = 1.2_c_double, sentinel = -12345.0_c_double
      real(c_double), parameter :: A = 1/(2*0.46_c_double), B = 1/(2*0.30_c_double)
      real(c_double), target :: h(n, n)
      real(c_double) :: hz(4), jg(4, 4), je(4, 4), scale(4), row_scale, dn, fd
      type(cw_grid) :: g
      type(cw_solver_type) :: gap, elliptic
      type(cw_params) :: p, q
      type(cw_result) :: rg, re, up, down
      integer :: row, k, stat
      character(len=:), allocatable :: message
      call hertz_gap(n, S, A, B, hz, g, h)
      call gap%create(grid=g)
      p = creep()
      p%gap = c_loc(h)
      p%gap_len = size(h, kind=c_size_t)
      call gap%solve_jacobian(p, jg, CW_SOLVE_FORCES, rg)
      call check_true(rg%n_slip > 0 .and. rg%n_adhesion > 0, 'gap Jacobian: partial slip')
      call elliptic%create(nx=n, ny=n, kind=CW_GRID_UNIFORM, box_scale=S)
      q = creep()
      q%a = hz(1)
      q%b = hz(2)
      call elliptic%solve_jacobian(q, je, CW_SOLVE_FORCES, re)
      scale = [1e-3_c_double, 1e-3_c_double, 1e-3_c_double/sqrt(hz(1)*hz(2)), load]
      dn = 1e-6_c_double*load
      q = p
      q%normal_force = load + dn
      call gap%solve(q, CW_SOLVE_FORCES, up)
      q%normal_force = load - dn
      call gap%solve(q, CW_SOLVE_FORCES, down)
      call check_int(up%n_contact, rg%n_contact, 'gap Jacobian: the step keeps the contact')
      call check_int(down%n_slip, rg%n_slip, 'gap Jacobian: the step keeps the states')
      do row = 1, 4
         row_scale = 0
         do k = 1, 4
            row_scale = row_scale + abs(je(row, k))*scale(k)
         end do
         do k = 1, 3
            call check_close(jg(row, k), je(row, k), 0.0_c_double, &
                             1e-8_c_double*row_scale/scale(k), 'gap Jacobian = elliptic (creepages)')
         end do
      end do
      do row = 1, 4
         row_scale = 0
         do k = 1, 4
            row_scale = row_scale + abs(jg(row, k))*scale(k)
         end do
         select case (row)
         case (1)
            fd = (up%Fx - down%Fx)/(2*dn)
         case (2)
            fd = (up%Fy - down%Fy)/(2*dn)
         case (3)
            fd = (up%Mz - down%Mz)/(2*dn)
         case default
            fd = (up%W_macro - down%W_macro)/(2*dn)
         end select
         call check_close(jg(row, 4), fd, 0.0_c_double, 1e-6_c_double*row_scale/scale(4), &
                          'gap Jacobian: N column vs central difference')
      end do
      ! No load: refused, naming normal_force, nothing written.
      jg = sentinel
      p%normal_force = 0
      call gap%solve_jacobian(p, jg, CW_SOLVE_FORCES, rg, stat=stat, errmsg=message)
      call check_int(stat, CW_ERR_INVALID_INPUT, 'gap Jacobian at N = 0: status')
      call check_true(index(message, 'normal_force') > 0, 'gap Jacobian at N = 0: names it')
      call check_true(all(jg == sentinel), 'gap Jacobian at N = 0: nothing written')
      call gap%destroy()
      call elliptic%destroy()
   end subroutine hertzian_gap_jacobian

end program test_fortran_gap
