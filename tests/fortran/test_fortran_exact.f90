! Cross-language identity of the exact model (and FASTSIM on the uniform
! grid): the contacts exact_language_cases.c solved through the C ABI (file
! given as argument 1) are solved again through module creepwork -- a fresh
! cw_solver_type made ready by %prepare(CW_MODEL_EXACT) -- and through the
! legacy CWSOLX. Every number must be bitwise identical to C's: forces,
! moment, work totals, K, p_max, approach, iteration count and residual,
! every field and state. Also: %prepare's errors (the exact model on the
! strip grid, an unknown model) and cw_batch_type%prepare.
program test_fortran_exact
   use, intrinsic :: iso_c_binding, only: c_double, c_int
   use creepwork
   use cw_test_support
   implicit none
   include 'creepwork_legacy.fi'

   integer, parameter :: line_capacity = 32768
   character(len=line_capacity) :: line
   character(len=:), allocatable :: path
   integer :: unit, ios, n_cases, n_fields
   type(cw_solver_type) :: solver
   type(cw_result) :: r
   integer :: nx = 0, ny = 0
   ! Legacy outputs of the current case, by CW_FIELD_* id (0..10) and states.
   real(c_double), allocatable :: legacy(:, :, :)
   integer(c_int), allocatable :: legacy_state(:, :)
   character(len=48) :: label

   call check_prepare_errors()
   n_cases = 0
   n_fields = 0
   path = command_argument(1)
   open (newunit=unit, file=path, status='old', action='read', iostat=ios)
   call check_true(ios == 0, 'open '//path)
   if (ios /= 0) call test_summary('test_fortran_exact')
   do
      read (unit, '(a)', iostat=ios) line
      if (ios /= 0) exit
      select case (line(1:1))
      case ('X')
         n_cases = n_cases + 1
         call solve_record(line(2:))
      case ('F')
         n_fields = n_fields + 1
         call field_record(line(2:))
      case ('Z')
         call state_record(line(2:))
      end select
   end do
   close (unit)
   call solver%destroy()
   ! The main program's allocatables are never freed by the runtime (LeakSanitizer).
   if (allocated(legacy)) deallocate (legacy, legacy_state)
   deallocate (path)
   call check_int(n_cases, 6, 'cases read (3 contacts x 2 models)')
   call check_int(n_fields, 6*11, 'fields read')
   call test_summary('test_fortran_exact')

contains

   subroutine solve_record(text)
      character(len=*), intent(in) :: text
      integer :: model, gnx, gny, n_slip, n_adhesion, iterations, stat, ierr
      real(c_double) :: box, c(22)
      type(cw_params) :: p
      real(c_double) :: fx, fy, fmz, wmac, wmic, ck, pmax, appr
      character(len=:), allocatable :: msg
      read (text, *) model, gnx, gny, box, c(1:9), c(10:18), n_slip, n_adhesion, iterations, &
         c(19)
      write (label, '(a,i0,a,i0,a,i0)') 'model ', model, ' grid ', gnx, 'x', gny
      nx = gnx
      ny = gny
      call solver%create(nx=nx, ny=ny, kind=int(CW_GRID_UNIFORM), box_scale=box)
      ! Everything the exact model needs, made before the solve.
      call solver%prepare(model, stat=stat, errmsg=msg)
      call check_int(stat, CW_OK, trim(label)//': prepare '//msg)
      call cw_params_init(p)
      p%model = model
      p%a = c(1)
      p%b = c(2)
      p%normal_force = c(3)
      p%mu = c(4)
      p%G = c(5)
      p%nu = c(6)
      p%xi_x = c(7)
      p%xi_y = c(8)
      p%phi = c(9)
      call cw_result_init(r)
      call solver%solve(p, CW_SOLVE_FULL, r)
      call check_same(r%Fx, c(10), trim(label)//' Fx')
      call check_same(r%Fy, c(11), trim(label)//' Fy')
      call check_same(r%Mz, c(12), trim(label)//' Mz')
      call check_same(r%W_macro, c(13), trim(label)//' W_macro')
      call check_same(r%W_micro_paper, c(14), trim(label)//' W_micro_paper')
      call check_same(r%K, c(15), trim(label)//' K')
      call check_same(r%W_consistent, c(16), trim(label)//' W_consistent')
      call check_same(r%p_max, c(17), trim(label)//' p_max')
      call check_same(r%approach, c(18), trim(label)//' approach')
      call check_int(r%n_slip, n_slip, trim(label)//' n_slip')
      call check_int(r%n_adhesion, n_adhesion, trim(label)//' n_adhesion')
      call check_int(r%iterations, iterations, trim(label)//' iterations')
      call check_same(r%residual, c(19), trim(label)//' residual')
      call check_int(r%model, model, trim(label)//' result model')
      if (model == CW_MODEL_EXACT) call check_true(r%iterations > 0, trim(label)//' iterated')
      ! The legacy entry, its own solver: the same numbers.
      if (allocated(legacy)) deallocate (legacy, legacy_state)
      allocate (legacy(nx, ny, 0:10), legacy_state(nx, ny))
      legacy = -1
      legacy_state = -1
      call CWSOLX(int(model, c_int), p%a, p%b, p%normal_force, p%mu, p%G, p%nu, p%xi_x, &
                  p%xi_y, p%phi, int(nx, c_int), int(ny, c_int), box, fx, fy, fmz, wmac, wmic, &
                  ck, pmax, appr, legacy(:, :, CW_FIELD_PX), legacy(:, :, CW_FIELD_PY), &
                  legacy(:, :, CW_FIELD_PZ), legacy(:, :, CW_FIELD_SX), &
                  legacy(:, :, CW_FIELD_SY), legacy(:, :, CW_FIELD_MZ), &
                  legacy(:, :, CW_FIELD_WORK_PAPER), legacy(:, :, CW_FIELD_WORK_CONSISTENT), &
                  legacy_state, ierr)
      call check_int(ierr, CW_OK, trim(label)//' CWSOLX IERR')
      call check_same(fx, c(10), trim(label)//' CWSOLX FX')
      call check_same(fy, c(11), trim(label)//' CWSOLX FY')
      call check_same(fmz, c(12), trim(label)//' CWSOLX FMZ')
      call check_same(wmac, c(13), trim(label)//' CWSOLX WMAC')
      call check_same(wmic, c(14), trim(label)//' CWSOLX WMIC')
      call check_same(ck, c(15), trim(label)//' CWSOLX CK')
      call check_same(pmax, c(17), trim(label)//' CWSOLX PMAX')
      call check_same(appr, c(18), trim(label)//' CWSOLX APPR')
   end subroutine solve_record

   subroutine field_record(text)
      character(len=*), intent(in) :: text
      integer :: field, n, k
      real(c_double), allocatable :: expected(:), got(:, :), flat(:)
      logical :: same_module, same_legacy
      read (text, *) field, n
      allocate (expected(n), got(nx, ny))
      read (text, *) field, n, expected
      call solver%get_field(field, got)
      flat = reshape(got, [n])
      same_module = all(flat == expected)
      if (.not. same_module) then
         k = findloc(flat == expected, .false., dim=1)
         write (*, '(a,i0,a,i0,2es25.17)') 'field ', field, ' element ', k, flat(k), expected(k)
      end if
      call check_true(same_module, trim(label)//' module field '//field_name(field))
      ! CWSOLX returns every field but the geometry (x, y, area).
      if (field >= CW_FIELD_PZ) then
         same_legacy = all(reshape(legacy(:, :, field), [n]) == expected)
         call check_true(same_legacy, trim(label)//' CWSOLX field '//field_name(field))
      end if
   end subroutine field_record

   subroutine state_record(text)
      character(len=*), intent(in) :: text
      integer :: n
      integer(c_int), allocatable :: expected(:), got(:, :)
      read (text, *) n
      allocate (expected(n), got(nx, ny))
      read (text, *) n, expected
      call solver%get_state(got)
      call check_true(all(reshape(got, [n]) == expected), trim(label)//' module states')
      call check_true(all(reshape(legacy_state, [n]) == expected), trim(label)//' CWSOLX ISTATE')
   end subroutine state_record

   function field_name(field) result(s)
      integer, intent(in) :: field
      character(len=:), allocatable :: s
      character(len=8) :: buf
      write (buf, '(i0)') field
      s = trim(buf)
   end function field_name

   ! prepare's errors come back through stat and errmsg, naming the cause;
   ! the batch's prepare reaches every thread's solver.
   subroutine check_prepare_errors()
      type(cw_solver_type) :: s
      type(cw_batch_type) :: batch
      type(cw_params) :: p
      type(cw_result) :: results(3), one
      integer :: stat, k
      character(len=:), allocatable :: msg
      call s%prepare(CW_MODEL_EXACT, stat=stat, errmsg=msg)
      call check_int(stat, CW_ERR_NULL_POINTER, 'prepare before create')
      call s%create(nx=8, ny=8) ! Kalker's strip grid
      call s%prepare(CW_MODEL_FASTSIM, stat=stat)
      call check_int(stat, CW_OK, 'prepare FASTSIM: nothing to do')
      call s%prepare(CW_MODEL_EXACT, stat=stat, errmsg=msg)
      call check_int(stat, CW_ERR_INVALID_INPUT, 'prepare exact on the strip grid')
      call check_true(index(msg, 'uniform') > 0 .or. index(msg, 'UNIFORM') > 0, &
                      'the message names the grid: '//msg)
      call s%prepare(7, stat=stat, errmsg=msg)
      call check_int(stat, CW_ERR_UNKNOWN_OPTION, 'prepare an unknown model')
      call s%destroy()
      ! Batch: prepared, then three exact contacts equal one-by-one solves.
      call batch%create(nx=12, ny=12, kind=int(CW_GRID_UNIFORM), box_scale=1.2_c_double, &
                        threads=2)
      call batch%prepare(CW_MODEL_EXACT, stat=stat, errmsg=msg)
      call check_int(stat, CW_OK, 'batch prepare: '//msg)
      call s%create(nx=12, ny=12, kind=int(CW_GRID_UNIFORM), box_scale=1.2_c_double)
      call cw_params_init(p)
      p%model = CW_MODEL_EXACT
      p%warm_start = 0
      block
         type(cw_params) :: ps(3)
         do k = 1, 3
            ps(k) = p
            ps(k)%xi_x = 2e-4_c_double*k
            ps(k)%phi = 0.3_c_double*(k - 2)
         end do
         call batch%solve(ps, CW_SOLVE_FORCES, results)
         do k = 1, 3
            call cw_result_init(one)
            call s%solve(ps(k), CW_SOLVE_FORCES, one)
            call check_same(results(k)%Fx, one%Fx, 'batch = one-by-one, Fx')
            call check_same(results(k)%Mz, one%Mz, 'batch = one-by-one, Mz')
         end do
      end block
      call batch%destroy()
      call batch%prepare(CW_MODEL_EXACT, stat=stat)
      call check_int(stat, CW_ERR_NULL_POINTER, 'batch prepare after destroy')
      call s%destroy()
   end subroutine check_prepare_errors

end program test_fortran_exact
