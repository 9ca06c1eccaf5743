! Dimensional solves of module creepwork (cw_solver_type, Kalker strip grid,
! parabolic bound) against the independent FORTRAN 77 reference FASTSIM
! (kalker_reference.f) over a sweep: pure and combined creepages, partial
! and full slip, a/b from 0.2 to 5, grids 5x5 to 100x100.
!
! Mapping of the dimensional inputs to Kalker's normalised ones (paper
! eqs. 13-25; core/model_setup.cpp): p0 = 2N/(pi a b), tractions in units
! mu p0, X = x/a, Y = y/b,
!   ux = a xi/(L1 mu p0), uy = a eta/(L2 mu p0),
!   cx = a b phi/(L3 mu p0), cy = a^2 phi/(L3 mu p0)  (rigid slip ux - Y cx, uy + X cy).
! The equal-strip grid of cw_solver is the reference run on ny equal strips.
! Asserts (second implementation of Kalker 1982, so the tolerance is
! rounding, 1e-12 relative):
!   Fx, Fy, Mz = mu p0 a b sum(...) of the reference; PX, PY element by
!   element; the adhesion/slip state of every element; the element centres.
program test_fortran_sweep
   use, intrinsic :: iso_c_binding, only: c_double, c_int
   use creepwork
   use cw_test_support
   implicit none
   external :: KRSIM

   real(c_double), parameter :: pi = 3.14159265358979323846_c_double
   real(c_double), parameter :: aspects(5) = [0.2_c_double, 0.5_c_double, 1.0_c_double, &
                                              2.0_c_double, 5.0_c_double]
   integer, parameter :: grids(2, 5) = reshape([5, 5, 8, 13, 20, 20, 40, 25, 100, 100], [2, 5])
   ! Creepages: xi [-], eta [-], phi [1/m]; small ones give partial slip,
   ! large ones full slip (checked below from the element states).
   integer, parameter :: n_cases = 8
   real(c_double), parameter :: creep(3, n_cases) = reshape([ &
                                1.0e-4_c_double, 0.0_c_double, 0.0_c_double, & ! pure longitudinal, partial
                                0.0_c_double, -3.0e-4_c_double, 0.0_c_double, & ! pure lateral, partial
                                0.0_c_double, 0.0_c_double, 0.5_c_double, &     ! pure spin, partial
                                4.0e-4_c_double, -2.0e-4_c_double, 0.3_c_double, & ! combined, partial
                                2.0e-2_c_double, 0.0_c_double, 0.0_c_double, &  ! pure longitudinal, full
                                0.0_c_double, 0.0_c_double, 40.0_c_double, &    ! pure spin, large
                                -5.0e-3_c_double, 8.0e-3_c_double, -6.0_c_double, & ! combined, full
                                1.0e-3_c_double, 1.0e-3_c_double, 2.0_c_double], & ! combined, mixed
                                [3, n_cases])
   integer :: ia, ig, ic, n_partial, n_full
   character(len=160) :: label

   n_partial = 0
   n_full = 0
   do ig = 1, size(grids, 2)
      do ia = 1, size(aspects)
         do ic = 1, n_cases
            write (label, '(a,f4.1,a,i0,a,i0,a,i0)') 'a/b=', aspects(ia), ' grid ', &
               grids(1, ig), 'x', grids(2, ig), ' case ', ic
            call compare(aspects(ia), grids(1, ig), grids(2, ig), creep(:, ic), trim(label))
         end do
      end do
   end do
   ! The sweep must really cover both regimes.
   call check_true(n_partial > 0, 'sweep contains partial-slip solves')
   call check_true(n_full > 0, 'sweep contains full-slip solves')
   call test_summary('test_fortran_sweep')

contains

   subroutine compare(aspect, nx, ny, c, label)
      real(c_double), intent(in) :: aspect, c(3)
      integer, intent(in) :: nx, ny
      character(len=*), intent(in) :: label
      type(cw_solver_type) :: solver
      type(cw_params) :: p
      type(cw_result) :: r
      real(c_double), allocatable :: px(:, :), py(:, :), x(:, :)
      real(c_double), allocatable :: rpx(:, :), rpy(:, :), xc(:, :)
      real(c_double), allocatable :: spx(:), spy(:), sxpy(:), dxs(:), ws(:), yc(:), yb(:)
      integer(c_int), allocatable :: state(:, :)
      integer, allocatable :: ist(:, :)
      real(c_double) :: p0, t, ux, uy, cx, cy, tx, ty, fx, fy, mz, area, pmax
      integer :: j, stat
      character(len=:), allocatable :: errmsg

      call cw_params_init(p)
      p%b = 6.0e-3_c_double
      p%a = aspect*p%b
      p%normal_force = 80.0e3_c_double
      p%mu = 0.3_c_double
      p%xi_x = c(1)
      p%xi_y = c(2)
      p%phi = c(3)
      call solver%create(nx=nx, ny=ny, kind=CW_GRID_KALKER_STRIPS, stat=stat, errmsg=errmsg)
      call check_int(stat, CW_OK, label//' create '//errmsg)
      call solver%solve(p, CW_SOLVE_FULL, r, stat=stat, errmsg=errmsg)
      call check_int(stat, CW_OK, label//' solve '//errmsg)
      allocate (px(nx, ny), py(nx, ny), x(nx, ny), state(nx, ny))
      call solver%get_field(CW_FIELD_PX, px)
      call solver%get_field(CW_FIELD_PY, py)
      call solver%get_field(CW_FIELD_X, x)
      call solver%get_state(state)
      call solver%destroy()

      ! Normalised inputs with the flexibilities the solver used.
      p0 = 2.0_c_double*p%normal_force/(pi*p%a*p%b)
      t = p%mu*p0
      ux = p%a*p%xi_x/r%L1/t
      uy = p%a*p%xi_y/r%L2/t
      cx = p%a*p%b*p%phi/r%L3/t
      cy = p%a*p%a*p%phi/r%L3/t
      allocate (rpx(nx, ny), rpy(nx, ny), xc(nx, ny), ist(nx, ny))
      allocate (spx(ny), spy(ny), sxpy(ny), dxs(ny), ws(ny), yc(ny), yb(0:ny))
      yb = [(-1.0_c_double + 2.0_c_double*j/ny, j=0, ny)]
      yb(ny) = 1.0_c_double
      call KRSIM(ux, uy, cx, cy, nx, ny, yb, rpx, rpy, ist, xc, spx, spy, sxpy, dxs, ws, yc, tx, ty)

      ! Totals: F = mu p0 a b sum_j dx_j w_j sum_i p', Mz = mu p0 sum_j area_j (a sum X py' - y sum px').
      fx = 0.0_c_double
      fy = 0.0_c_double
      mz = 0.0_c_double
      do j = 1, ny
         area = p%a*p%b*dxs(j)*ws(j)
         fx = fx + area*spx(j)
         fy = fy + area*spy(j)
         mz = mz + area*(p%a*sxpy(j) - p%b*yc(j)*spx(j))
      end do
      fx = t*fx
      fy = t*fy
      mz = t*mz
      call check_close(r%Fx, fx, 1e-12_c_double, 1e-12_c_double*abs(fy), label//' Fx')
      call check_close(r%Fy, fy, 1e-12_c_double, 1e-12_c_double*abs(fx), label//' Fy')
      call check_close(r%Mz, mz, 1e-12_c_double, &
                       1e-12_c_double*max(p%a, p%b)*(abs(fx) + abs(fy)), label//' Mz')
      ! Element by element: tractions [Pa] (units mu p0 in the reference), centres, states.
      pmax = t*max(maxval(abs(rpx)), maxval(abs(rpy)))
      call check_true(all(abs(px - t*rpx) <= 1e-12_c_double*pmax), label//' PX map')
      call check_true(all(abs(py - t*rpy) <= 1e-12_c_double*pmax), label//' PY map')
      call check_true(all(abs(x - p%a*xc) <= 1e-14_c_double*p%a), label//' element centres x')
      call check_true(all(state == ist), label//' adhesion/slip states')
      if (any(ist == 1) .and. any(ist == 2)) n_partial = n_partial + 1
      if (all(ist == 2)) n_full = n_full + 1
   end subroutine compare

end program test_fortran_sweep
