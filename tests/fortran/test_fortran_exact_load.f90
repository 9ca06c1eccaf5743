! cw_params%exact_load through module creepwork: the field is part of the
! bind(C) mirror of cw_params, so solve, solve_jacobian and the batch pass it
! as they pass every field. Expected values:
!   - Coulomb's law: in full sliding along x every contact element carries
!     mu pz, so |Fx| = mu sum(pz area) = mu N to rounding when the discrete
!     load is N (exact_load = 1), on Kalker's strips and CONTACT's uniform
!     grid, FASTSIM and the calibrated model;
!   - the default (exact_load = 0) keeps the analytic pressure scale, whose
!     midpoint sum over the grid differs from N (by 0.15 % on 20 x 20
!     strips): |Fx| = mu sum(pz area) there, more than 1e-4 away from mu N;
!   - solve_jacobian reports the same totals as solve (the header: bitwise),
!     and the batch the same as one-by-one solves (the header: bitwise), so
!     both carry the option.
program test_fortran_exact_load
   use, intrinsic :: iso_c_binding, only: c_double
   use creepwork
   use cw_test_support
   implicit none

   call full_sliding(CW_GRID_KALKER_STRIPS, 20, 20, CW_MODEL_FASTSIM, 'FASTSIM strips 20 x 20')
   call full_sliding(CW_GRID_UNIFORM, 15, 9, CW_MODEL_FASTSIM, 'FASTSIM uniform 15 x 9')
   call full_sliding(CW_GRID_KALKER_STRIPS, 20, 20, CW_MODEL_CALIBRATED, 'calibrated strips 20 x 20')
   call default_scale()
   call jacobian_and_batch()
   call test_summary('test_fortran_exact_load')

contains

   function contact(xi_x, exact_load, model) result(p)
      real(c_double), intent(in) :: xi_x
      integer, intent(in) :: exact_load, model
      type(cw_params) :: p
      call cw_params_init(p)
      p%a = 7.17e-3_c_double
      p%b = 5.42e-3_c_double
      p%normal_force = 100e3_c_double
      p%model = model
      p%xi_x = xi_x
      p%exact_load = exact_load
   end function contact

   ! sum(pz * area) of the solver's last solve.
   function discrete_load(s) result(load)
      type(cw_solver_type), intent(in) :: s
      real(c_double) :: load
      real(c_double), allocatable :: pz(:, :), area(:, :)
      integer :: nx, ny
      call s%grid_size(nx, ny)
      allocate (pz(nx, ny), area(nx, ny))
      call s%get_field(CW_FIELD_PZ, pz)
      call s%get_field(CW_FIELD_AREA, area)
      load = sum(pz*area)
   end function discrete_load

   subroutine full_sliding(kind, nx, ny, model, label)
      integer, intent(in) :: kind, nx, ny, model
      character(len=*), intent(in) :: label
      type(cw_solver_type) :: s
      type(cw_params) :: p
      type(cw_result) :: r
      call s%create(nx=nx, ny=ny, kind=kind)
      p = contact(0.3_c_double, 1, model)
      call s%solve(p, CW_SOLVE_FULL, r)
      call check_int(r%n_adhesion, 0, label//': full sliding at xi_x = 0.3')
      call check_close(discrete_load(s), p%normal_force, 1e-12_c_double, 0.0_c_double, &
                       label//': sum(pz area) = N')
      ! On the wheel, opposite to xi_x.
      call check_close(-r%Fx, p%mu*p%normal_force, 1e-12_c_double, 0.0_c_double, &
                       label//': |Fx| = mu N')
      call s%destroy()
   end subroutine full_sliding

   subroutine default_scale()
      type(cw_solver_type) :: s
      type(cw_params) :: p
      type(cw_result) :: r
      real(c_double) :: load
      call s%create(nx=20, ny=20)
      p = contact(0.3_c_double, 0, CW_MODEL_FASTSIM)
      call s%solve(p, CW_SOLVE_FULL, r)
      load = discrete_load(s)
      call check_true(abs(load/p%normal_force - 1) > 1e-4_c_double, &
                      'default: the discrete load differs from N')
      call check_close(-r%Fx, p%mu*load, 1e-12_c_double, 0.0_c_double, &
                       'default: |Fx| = mu sum(pz area)')
      call check_true(abs(-r%Fx/(p%mu*p%normal_force) - 1) > 1e-4_c_double, &
                      'default: |Fx| is not mu N')
      call s%destroy()
   end subroutine default_scale

   subroutine jacobian_and_batch()
      integer, parameter :: n = 4
      type(cw_solver_type) :: s
      type(cw_batch_type) :: batch
      type(cw_params) :: p(n)
      type(cw_result) :: one, jac_result, results(n)
      real(c_double) :: jacobian(4, 4)
      integer :: k
      call s%create(nx=20, ny=20)
      call batch%create(nx=20, ny=20, threads=2)
      do k = 1, n
         p(k) = contact(1e-3_c_double*k**2, mod(k, 2), CW_MODEL_FASTSIM)
         p(k)%xi_y = -4e-4_c_double
         p(k)%phi = 0.5_c_double
      end do
      p(n)%xi_x = 0.3_c_double ! full sliding along x
      p(n)%xi_y = 0
      p(n)%phi = 0
      call batch%solve(p, CW_SOLVE_FORCES, results)
      do k = 1, n
         call s%solve(p(k), CW_SOLVE_FORCES, one)
         call check_same(results(k)%Fx, one%Fx, 'batch Fx = solve Fx')
         call check_same(results(k)%Mz, one%Mz, 'batch Mz = solve Mz')
         call s%solve_jacobian(p(k), jacobian, CW_SOLVE_FORCES, jac_result)
         call check_same(jac_result%Fx, one%Fx, 'solve_jacobian Fx = solve Fx')
         call check_same(jac_result%Fy, one%Fy, 'solve_jacobian Fy = solve Fy')
      end do
      ! Case n (exact_load = 0) and the same with exact_load = 1 differ by the
      ! ratio of the discrete load to N: the batch did not drop the field.
      p(n)%exact_load = 1
      call batch%solve(p(n:n), CW_SOLVE_FORCES, results(1:1))
      call check_close(-results(1)%Fx, p(n)%mu*p(n)%normal_force, 1e-12_c_double, &
                       0.0_c_double, 'batch with exact_load: |Fx| = mu N in full sliding')
      call check_true(abs(results(1)%Fx/results(n)%Fx - 1) > 1e-4_c_double, &
                      'batch: exact_load changes the saturated force')
      call batch%destroy()
      call s%destroy()
   end subroutine jacobian_and_batch

end program test_fortran_exact_load
