! A Fortran host that traps floating-point exceptions, as legacy codes are
! built: CTest compiles this program twice, with
! -ffpe-trap=invalid,zero,overflow,denormal (test_fortran_fptrap: any
! exception kills it with SIGFPE) and without (test_fortran_fpnote: at the
! final STOP, gfortran notes every exception flag still raised, e.g.
! "IEEE_DENORMAL"; CTest fails on such a note). Both run the module and the
! legacy layer over a sweep of contacts and grids, hostile inputs included
! (NaN, Inf, 1e300, subnormal), so neither traps nor flags may come out of
! the library (doc/reference/guarantees.md). The program's own arithmetic is kept
! free of exceptions.
program fortran_fptrap
   use, intrinsic :: iso_c_binding, only: c_double, c_int
   use, intrinsic :: ieee_arithmetic, only: ieee_value, ieee_quiet_nan, ieee_positive_inf
   use creepwork
   implicit none
   include 'creepwork_legacy.fi'
   integer, parameter :: ngrids = 5
   integer, parameter :: kinds(ngrids) = [CW_GRID_KALKER_STRIPS, CW_GRID_KALKER_STRIPS, &
                                          CW_GRID_UNIFORM, CW_GRID_UNIFORM, CW_GRID_UNIFORM]
   integer, parameter :: nxs(ngrids) = [1, 7, 14, 33, 44], nys(ngrids) = [1, 7, 16, 9, 44]
   real(c_double), parameter :: creepages(7) = [0.0_c_double, 1e-9_c_double, 1e-4_c_double, &
                                                1e-3_c_double, 1e-2_c_double, 1.0_c_double, &
                                                1e6_c_double]
   real(c_double), parameter :: spins_a(4) = [0.0_c_double, 0.05_c_double, 1.0_c_double, &
                                              -100.0_c_double]
   type(cw_solver_type) :: solver
   type(cw_accumulator_type) :: acc
   type(cw_params) :: p
   type(cw_result) :: r
   real(c_double), allocatable :: field(:, :), strips(:)
   integer(c_int), allocatable :: states(:, :)
   integer :: g, c, w, pr, d, opt, f, mode, stat, calls
   calls = 0

   do g = 1, ngrids
      call solver%create(nx=nxs(g), ny=nys(g), kind=kinds(g), box_scale=1.1_c_double)
      call acc%create(solver)
      allocate (field(nxs(g), nys(g)), states(nxs(g), nys(g)), strips(nys(g)))
      do c = 1, size(creepages)
         do w = 1, size(spins_a)
            do pr = CW_PRESSURE_PARABOLIC, CW_PRESSURE_ELLIPTIC
               do d = -1, 1, 2
                  do opt = 0, 1
                     call cw_params_init(p)
                     p%xi_x = creepages(c)
                     p%xi_y = -0.5_c_double*creepages(c)
                     p%phi = spins_a(w)/p%a
                     p%pressure = pr
                     p%rolling_direction = d
                     if (opt == 1) then
                        p%spin_offset = 1.0_c_double/6.0_c_double
                        p%flexibility_blending = 1
                     end if
                     do mode = CW_SOLVE_FORCES, CW_SOLVE_FULL
                        call solver%solve(p, mode, r)
                        calls = calls + 1
                     end do
                     do f = CW_FIELD_X, CW_FIELD_WORK_CONSISTENT
                        call solver%get_field(f, field)
                     end do
                     call solver%get_state(states)
                     call solver%get_profile(w=strips)
                     call acc%add(solver, 0.01_c_double)
                     calls = calls + 14
                  end do
               end do
            end do
         end do
      end do
      call acc%destroy()
      call solver%destroy()
      deallocate (field, states, strips)
   end do

   call legacy_calls(calls)
   call hostile_calls(calls)
   write (*, '(a,i0,a)') 'fortran: ', calls, ' calls with traps on'
   stop
contains

   ! Every legacy routine on ordinary input.
   subroutine legacy_calls(calls)
      integer, intent(inout) :: calls
      integer(c_int), parameter :: nx = 12, ny = 10
      real(c_double), dimension(nx, ny) :: px, py, sx, sy, zmap, wpap, wcon, wpacc, wcacc
      integer(c_int) :: istate(nx, ny), ierr, k
      real(c_double) :: fx, fy, fmz, wmac, wmic, ck, l1, l2, l3, c11, c22, c23, c33
      real(c_double) :: a, b, p0, appr, tx, ty, dsum, wmsum, wpsum, ckrun
      dsum = 0
      wmsum = 0
      wpsum = 0
      wpacc = 0
      wcacc = 0
      do k = 0, 6
         call CWSOLM(6e-3_c_double, 4e-3_c_double, 8e4_c_double, 0.3_c_double, 82e9_c_double, &
                     0.28_c_double, 1e-4_c_double*k**2, -3e-4_c_double*k, 0.3_c_double*k, nx, &
                     ny, fx, fy, fmz, wmac, wmic, ck, px, py, sx, sy, zmap, wpap, wcon, istate, &
                     ierr)
         call CWACCU(nx, ny, 0.03_c_double, wmac, wmic, wpap, wcon, dsum, wmsum, wpsum, wpacc, &
                     wcacc, ckrun, ierr)
         call CWFLEX(6e-3_c_double, 4e-3_c_double, 82e9_c_double, 0.28_c_double, l1, l2, l3, ierr)
         call CWSOLL(6e-3_c_double, 4e-3_c_double, 8e4_c_double, 0.3_c_double, l1, l2, l3, &
                     1e-4_c_double*k, 0.0_c_double, 0.0_c_double, nx, ny, fx, fy, fmz, wmac, &
                     wmic, ck, px, py, sx, sy, zmap, wpap, wcon, istate, ierr)
         call CWFSIM(0.1_c_double*k, -0.2_c_double, 0.05_c_double*k, 0.08_c_double*k, 10_c_int, &
                     10_c_int, 1e-3_c_double, tx, ty, ierr)
         call CWKALK(0.2_c_double*(k + 1), 0.28_c_double, c11, c22, c23, c33, ierr)
         call CWHERT(0.5_c_double*(k + 1), 1.5_c_double, 1e5_c_double, 1.1e11_c_double, a, b, &
                     p0, appr, ierr)
         calls = calls + 7
      end do
   end subroutine legacy_calls

   ! Hostile and absurd input: a status, never a trap.
   subroutine hostile_calls(calls)
      integer, intent(inout) :: calls
      integer(c_int), parameter :: nx = 6, ny = 6
      real(c_double), dimension(nx, ny) :: px, py, sx, sy, zmap, wpap, wcon, wpacc, wcacc
      integer(c_int) :: istate(nx, ny), ierr, k
      real(c_double) :: fx, fy, fmz, wmac, wmic, ck, tx, ty, dsum, wmsum, wpsum, ckrun
      real(c_double) :: bad(6)
      type(cw_result) :: res
      bad = [ieee_value(1.0_c_double, ieee_quiet_nan), ieee_value(1.0_c_double, ieee_positive_inf), &
             -1.0_c_double, 1e300_c_double, 1e-310_c_double, 0.0_c_double]
      wpap = 1.0_c_double
      wcon = 1.0_c_double
      do k = 1, size(bad)
         call CWSOLM(bad(k), 4e-3_c_double, 8e4_c_double, 0.3_c_double, 82e9_c_double, &
                     0.28_c_double, 1e-3_c_double, 0.0_c_double, 0.0_c_double, nx, ny, fx, fy, &
                     fmz, wmac, wmic, ck, px, py, sx, sy, zmap, wpap, wcon, istate, ierr)
         call CWSOLM(6e-3_c_double, 4e-3_c_double, bad(k), 0.3_c_double, 82e9_c_double, &
                     0.28_c_double, bad(k), 0.0_c_double, bad(k), nx, ny, fx, fy, fmz, wmac, &
                     wmic, ck, px, py, sx, sy, zmap, wpap, wcon, istate, ierr)
         call CWFSIM(bad(k), 0.1_c_double, bad(k), 0.0_c_double, 5_c_int, 5_c_int, bad(k), tx, &
                     ty, ierr)
         dsum = 0
         wmsum = 0
         wpsum = 0
         wpacc = 0
         wcacc = 0
         call CWACCU(nx, ny, bad(k), 1e300_c_double, 1.0_c_double, wpap, wcon, dsum, wmsum, &
                     wpsum, wpacc, wcacc, ckrun, ierr)
         call CWACCU(nx, ny, 1e300_c_double, bad(k), bad(k), wpap, wcon, dsum, wmsum, wpsum, &
                     wpacc, wcacc, ckrun, ierr)
         call cw_params_init(p)
         p%mu = bad(k)
         p%phi = bad(k)
         call solver%create(nx=8, ny=8)
         call solver%solve(p, CW_SOLVE_FULL, res, stat=stat)
         call solver%destroy()
         calls = calls + 7
      end do
   end subroutine hostile_calls

end program fortran_fptrap
