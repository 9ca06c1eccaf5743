! Cross-language identity: the cases that cross_language_cases.c solved
! through the C ABI (file given as argument 1) are solved again through
! module creepwork and, where the legacy layer covers them (Kalker strips,
! parabolic bound, rolling towards +x), through CWFSIM / CWSOLM / CWSOLL and
! CWACCU. Every number must be bitwise identical to C's: forces, moment,
! work totals and K, every field and state of each solve, its wear strips
! (module get_strips: y, width, depth, parabola in the header's order;
! legacy CWWEAR: YS, DYS, DEPTH), and the totals and maps of a 60-step
! accumulation (C accumulator = module accumulator = legacy CWACCU). The
! only allowed difference between the paths is none.
program test_fortran_cross
   use, intrinsic :: iso_c_binding, only: c_double, c_int, c_int64_t
   use creepwork
   use cw_test_support
   implicit none
   external :: CWFSIM, CWSOLM, CWSOLL, CWACCU, CWWEAR

   integer, parameter :: line_capacity = 16384
   character(len=line_capacity) :: line
   character(len=:), allocatable :: path
   integer :: unit, ios, n_records(9)

   ! The current dimensional case: module maps for every field, the legacy
   ! maps when the legacy layer covers the case.
   real(c_double), allocatable :: module_maps(:, :), legacy_maps(:, :)
   integer(c_int), allocatable :: module_states(:), legacy_states(:)
   ! Its wear strips (columns y, width, depth, parabola; the legacy CWWEAR's
   ! first three when it covers the case: flexibilities from the material).
   real(c_double), allocatable :: module_strips(:, :), legacy_strips(:, :)
   logical :: have_legacy = .false., have_legacy_wear = .false.
   integer :: case_no = 0

   ! The accumulation replay.
   type(cw_solver_type) :: acc_solver
   type(cw_accumulator_type) :: acc
   type(cw_params) :: acc_params
   integer :: acc_nx = 0, acc_ny = 0
   real(c_double), allocatable :: l_wpap(:, :), l_wcon(:, :), l_px(:, :), l_py(:, :), l_sx(:, :)
   real(c_double), allocatable :: l_sy(:, :), l_zmap(:, :), l_wpacc(:, :), l_wcacc(:, :)
   integer(c_int), allocatable :: l_state(:, :)
   real(c_double) :: l_dsum = 0, l_wmsum = 0, l_wpsum = 0, l_krun = 0

   n_records = 0
   path = command_argument(1)
   open (newunit=unit, file=path, status='old', action='read', iostat=ios)
   call check_true(ios == 0, 'open '//path)
   if (ios /= 0) call test_summary('test_fortran_cross')
   do
      read (unit, '(a)', iostat=ios) line
      if (ios /= 0) exit
      select case (line(1:1))
      case ('N')
         n_records(1) = n_records(1) + 1
         call normalised_record(line(2:))
      case ('S')
         n_records(2) = n_records(2) + 1
         call solve_record(line(2:))
      case ('F')
         n_records(3) = n_records(3) + 1
         call field_record(line(2:))
      case ('Z')
         n_records(4) = n_records(4) + 1
         call state_record(line(2:))
      case ('B')
         n_records(5) = n_records(5) + 1
         call begin_accumulation(line(2:))
      case ('A')
         n_records(6) = n_records(6) + 1
         call step_record(line(2:))
      case ('T')
         n_records(7) = n_records(7) + 1
         call totals_record(line(2:))
      case ('W')
         n_records(8) = n_records(8) + 1
         call accumulated_map_record(line(2:))
      case ('R')
         n_records(9) = n_records(9) + 1
         call strips_record(line(2:))
      end select
   end do
   close (unit)
   ! The C program wrote 8 normalised cases, 5 solves of 11 fields each
   ! with their states and wear strips, one accumulation of 60 steps with 2
   ! maps.
   call check_true(all(n_records == [8, 5, 55, 5, 1, 60, 1, 2, 5]), &
                   'every record of the C file seen')
   call acc%destroy()
   call acc_solver%destroy()
   ! Main-program allocatables are not freed at the end (LeakSanitizer).
   if (allocated(module_maps)) deallocate (module_maps, module_states)
   if (allocated(legacy_maps)) deallocate (legacy_maps, legacy_states)
   if (allocated(module_strips)) deallocate (module_strips)
   if (allocated(legacy_strips)) deallocate (legacy_strips)
   if (allocated(l_wpap)) deallocate (l_wpap, l_wcon, l_px, l_py, l_sx, l_sy, l_zmap, l_wpacc, &
                                      l_wcacc, l_state)
   deallocate (path)
   call test_summary('test_fortran_cross')

contains

   subroutine normalised_record(text)
      character(len=*), intent(in) :: text
      real(c_double) :: ux, uy, fx, fy, tol, tx_c, ty_c, tx, ty, tx_l, ty_l
      integer :: mx, my, ierr
      read (text, *) ux, uy, fx, fy, mx, my, tol, tx_c, ty_c
      call cw_fastsim_normalised(ux, uy, fx, fy, mx, my, tol, tx, ty)
      call check_same(tx, tx_c, 'normalised TX module = C')
      call check_same(ty, ty_c, 'normalised TY module = C')
      call CWFSIM(ux, uy, fx, fy, mx, my, tol, tx_l, ty_l, ierr)
      call check_int(ierr, 0, 'CWFSIM IERR')
      call check_same(tx_l, tx_c, 'normalised TX legacy = C')
      call check_same(ty_l, ty_c, 'normalised TY legacy = C')
   end subroutine normalised_record

   subroutine solve_record(text)
      character(len=*), intent(in) :: text
      integer :: kind, nx, ny, pressure, flexibility, direction, n_slip, field, ierr
      real(c_double) :: c(12), t(7)
      type(cw_solver_type) :: s
      type(cw_wear_type) :: wear
      type(cw_params) :: p
      type(cw_result) :: r
      real(c_double) :: fx, fy, fmz, wmac, wmic, ck, wmass
      real(c_double), allocatable :: px(:, :), py(:, :), sx(:, :), sy(:, :), zmap(:, :)
      real(c_double), allocatable :: wpap(:, :), wcon(:, :)
      integer(c_int), allocatable :: istate(:, :)
      character(len=32) :: label

      case_no = case_no + 1
      write (label, '(a,i0,a)') 'solve ', case_no, ': '
      read (text, *) kind, nx, ny, pressure, flexibility, direction, c, t, n_slip
      call cw_params_init(p)
      p%a = c(1)
      p%b = c(2)
      p%normal_force = c(3)
      p%mu = c(4)
      p%G = c(5)
      p%nu = c(6)
      p%L1 = c(7)
      p%L2 = c(8)
      p%L3 = c(9)
      p%xi_x = c(10)
      p%xi_y = c(11)
      p%phi = c(12)
      p%pressure = pressure
      p%flexibility = flexibility
      p%rolling_direction = direction
      call s%create(kind=kind, nx=nx, ny=ny, box_scale=1.1_c_double)
      call s%solve(p, CW_SOLVE_FULL, r)
      call check_same(r%Fx, t(1), trim(label)//'Fx module = C')
      call check_same(r%Fy, t(2), trim(label)//'Fy module = C')
      call check_same(r%Mz, t(3), trim(label)//'Mz module = C')
      call check_same(r%W_macro, t(4), trim(label)//'W_macro module = C')
      call check_same(r%W_micro_paper, t(5), trim(label)//'W_micro_paper module = C')
      call check_same(r%K, t(6), trim(label)//'K module = C')
      call check_same(r%W_consistent, t(7), trim(label)//'W_consistent module = C')
      call check_int(r%n_slip, n_slip, trim(label)//'n_slip module = C')
      if (allocated(module_maps)) deallocate (module_maps, module_states)
      allocate (module_maps(nx*ny, CW_FIELD_X:CW_FIELD_WORK_CONSISTENT), module_states(nx*ny))
      do field = CW_FIELD_X, CW_FIELD_WORK_CONSISTENT
         call s%get_field(field, module_maps(:, field))
      end do
      call s%get_state(module_states)
      if (allocated(module_strips)) deallocate (module_strips)
      allocate (module_strips(ny, 4))
      call wear%create(s)
      call wear%compute(s) ! USFD, the defaults
      call wear%get_strips(y=module_strips(:, 1), width=module_strips(:, 2), &
                           depth=module_strips(:, 3), parabola=module_strips(:, 4))
      call wear%destroy()
      call s%destroy()

      have_legacy = kind == CW_GRID_KALKER_STRIPS .and. pressure == CW_PRESSURE_PARABOLIC .and. &
                    direction == 1
      have_legacy_wear = have_legacy .and. flexibility == CW_FLEX_FROM_MATERIAL
      if (have_legacy_wear) then
         if (allocated(legacy_strips)) deallocate (legacy_strips)
         allocate (legacy_strips(ny, 3))
         call CWWEAR(p%a, p%b, p%normal_force, p%mu, p%G, p%nu, p%xi_x, p%xi_y, p%phi, nx, ny, &
                     0_c_int, 0.0_c_double, legacy_strips(:, 1), legacy_strips(:, 2), &
                     legacy_strips(:, 3), wmass, ierr)
         call check_int(ierr, 0, trim(label)//'CWWEAR IERR')
      end if
      if (.not. have_legacy) return
      allocate (px(nx, ny), py(nx, ny), sx(nx, ny), sy(nx, ny), zmap(nx, ny), wpap(nx, ny), &
                wcon(nx, ny), istate(nx, ny))
      if (flexibility == CW_FLEX_FROM_MATERIAL) then
         call CWSOLM(p%a, p%b, p%normal_force, p%mu, p%G, p%nu, p%xi_x, p%xi_y, p%phi, nx, ny, &
                     fx, fy, fmz, wmac, wmic, ck, px, py, sx, sy, zmap, wpap, wcon, istate, ierr)
      else
         call CWSOLL(p%a, p%b, p%normal_force, p%mu, p%L1, p%L2, p%L3, p%xi_x, p%xi_y, p%phi, &
                     nx, ny, fx, fy, fmz, wmac, wmic, ck, px, py, sx, sy, zmap, wpap, wcon, &
                     istate, ierr)
      end if
      call check_int(ierr, 0, trim(label)//'legacy IERR')
      call check_same(fx, t(1), trim(label)//'Fx legacy = C')
      call check_same(fy, t(2), trim(label)//'Fy legacy = C')
      call check_same(fmz, t(3), trim(label)//'Mz legacy = C')
      call check_same(wmac, t(4), trim(label)//'W_macro legacy = C')
      call check_same(wmic, t(5), trim(label)//'W_micro_paper legacy = C')
      call check_same(ck, t(6), trim(label)//'K legacy = C')
      if (allocated(legacy_maps)) deallocate (legacy_maps, legacy_states)
      allocate (legacy_maps(nx*ny, CW_FIELD_PX:CW_FIELD_WORK_CONSISTENT), legacy_states(nx*ny))
      legacy_maps(:, CW_FIELD_PX) = reshape(px, [nx*ny])
      legacy_maps(:, CW_FIELD_PY) = reshape(py, [nx*ny])
      legacy_maps(:, CW_FIELD_SX) = reshape(sx, [nx*ny])
      legacy_maps(:, CW_FIELD_SY) = reshape(sy, [nx*ny])
      legacy_maps(:, CW_FIELD_MZ) = reshape(zmap, [nx*ny])
      legacy_maps(:, CW_FIELD_WORK_PAPER) = reshape(wpap, [nx*ny])
      legacy_maps(:, CW_FIELD_WORK_CONSISTENT) = reshape(wcon, [nx*ny])
      legacy_states = reshape(istate, [nx*ny])
   end subroutine solve_record

   subroutine field_record(text)
      character(len=*), intent(in) :: text
      integer :: field, n
      real(c_double), allocatable :: v(:)
      character(len=48) :: label
      read (text, *) field, n
      allocate (v(n))
      read (text, *) field, n, v
      write (label, '(a,i0,a,i0)') 'solve ', case_no, ' field ', field
      call check_int(n, size(module_maps, 1), trim(label)//' size')
      if (n /= size(module_maps, 1)) return
      call check_true(all(module_maps(:, field) == v), trim(label)//' module = C, every element')
      if (have_legacy .and. field >= CW_FIELD_PX) &
         call check_true(all(legacy_maps(:, field) == v), trim(label)//' legacy = C, every element')
   end subroutine field_record

   subroutine state_record(text)
      character(len=*), intent(in) :: text
      integer :: n
      integer, allocatable :: v(:)
      read (text, *) n
      allocate (v(n))
      read (text, *) n, v
      call check_true(all(module_states == v), 'states module = C')
      if (have_legacy) call check_true(all(legacy_states == v), 'states legacy = C')
   end subroutine state_record

   subroutine strips_record(text)
      character(len=*), intent(in) :: text
      character(len=*), parameter :: names(4) = [character(len=8) :: 'y', 'width', 'depth', &
                                                 'parabola']
      integer :: ny, n, k
      real(c_double), allocatable :: v(:)
      character(len=48) :: label
      read (text, *) ny, n
      allocate (v(n))
      read (text, *) ny, n, v
      call check_int(n, 4*size(module_strips, 1), 'strips: 4 ny values')
      if (n /= 4*size(module_strips, 1)) return
      do k = 1, 4
         write (label, '(a,i0,a,a)') 'solve ', case_no, ' strips ', trim(names(k))
         call check_true(all(module_strips(:, k) == v((k - 1)*ny + 1:k*ny)), &
                         trim(label)//' module = C')
         if (have_legacy_wear .and. k <= 3) &
            call check_true(all(legacy_strips(:, k) == v((k - 1)*ny + 1:k*ny)), &
                            trim(label)//' CWWEAR = C')
      end do
   end subroutine strips_record

   subroutine begin_accumulation(text)
      character(len=*), intent(in) :: text
      call cw_params_init(acc_params)
      read (text, *) acc_nx, acc_ny, acc_params%a, acc_params%b
      call acc_solver%create(nx=acc_nx, ny=acc_ny)
      call acc%create(acc_solver)
      allocate (l_wpap(acc_nx, acc_ny), l_wcon(acc_nx, acc_ny), l_px(acc_nx, acc_ny), &
                l_py(acc_nx, acc_ny), l_sx(acc_nx, acc_ny), l_sy(acc_nx, acc_ny), &
                l_zmap(acc_nx, acc_ny), l_wpacc(acc_nx, acc_ny), l_wcacc(acc_nx, acc_ny), &
                l_state(acc_nx, acc_ny))
      l_wpacc = 0
      l_wcacc = 0
   end subroutine begin_accumulation

   subroutine step_record(text)
      character(len=*), intent(in) :: text
      real(c_double) :: distance, fx, fy, fmz, wmac, wmic, ck
      integer :: ierr
      read (text, *) acc_params%xi_x, acc_params%xi_y, acc_params%phi, distance
      call acc_solver%solve(acc_params, CW_SOLVE_FULL)
      call acc%add(acc_solver, distance)
      call CWSOLM(acc_params%a, acc_params%b, acc_params%normal_force, acc_params%mu, &
                  acc_params%G, acc_params%nu, acc_params%xi_x, acc_params%xi_y, acc_params%phi, &
                  acc_nx, acc_ny, fx, fy, fmz, wmac, wmic, ck, l_px, l_py, l_sx, l_sy, l_zmap, &
                  l_wpap, l_wcon, l_state, ierr)
      call check_int(ierr, 0, 'accumulation step: CWSOLM')
      call CWACCU(acc_nx, acc_ny, distance, wmac, wmic, l_wpap, l_wcon, l_dsum, l_wmsum, l_wpsum, &
                  l_wpacc, l_wcacc, l_krun, ierr)
      call check_int(ierr, 0, 'accumulation step: CWACCU')
   end subroutine step_record

   subroutine totals_record(text)
      character(len=*), intent(in) :: text
      real(c_double) :: c(5)
      integer(c_int64_t) :: steps
      type(cw_accumulation) :: t
      read (text, *) c, steps
      call acc%get_totals(t)
      call check_same(t%distance, c(1), 'accumulated distance module = C')
      call check_same(t%W_macro, c(2), 'accumulated W_macro (eq. 35) module = C')
      call check_same(t%W_micro_paper, c(3), 'accumulated W_micro (eq. 37) module = C')
      call check_same(t%K, c(4), 'K over the run module = C')
      call check_same(t%W_consistent, c(5), 'accumulated W_consistent module = C')
      call check_true(t%steps == steps, 'steps module = C')
      call check_same(l_dsum, c(1), 'accumulated distance legacy = C')
      call check_same(l_wmsum, c(2), 'accumulated W_macro legacy = C')
      call check_same(l_wpsum, c(3), 'accumulated W_micro legacy = C')
      call check_same(l_krun, c(4), 'K over the run legacy = C')
   end subroutine totals_record

   subroutine accumulated_map_record(text)
      character(len=*), intent(in) :: text
      integer :: field, n
      real(c_double), allocatable :: v(:), m(:)
      read (text, *) field, n
      allocate (v(n), m(n))
      read (text, *) field, n, v
      call acc%get_field(field, m)
      call check_true(all(m == v), 'accumulated map module = C')
      if (field == CW_FIELD_WORK_PAPER) then
         call check_true(all(reshape(l_wpacc, [n]) == v), 'accumulated paper map legacy = C')
      else
         call check_true(all(reshape(l_wcacc, [n]) == v), 'accumulated consistent map legacy = C')
      end if
   end subroutine accumulated_map_record

end program test_fortran_cross
