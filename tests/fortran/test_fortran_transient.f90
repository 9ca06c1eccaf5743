! Transient rolling through module creepwork (cw_transient_type) on CONTACT's
! catt_to_cart (a sphere on 34 x 33 cells of 0.25 mm; the contact as in
! transient_language_cases.c):
!   bits      the Cattaneo shift to Fx = -0.657 mu N and 14 rolling steps,
!             then a rewound trial and a trial at Fx = -0.5 mu N: every
!             total, the px and sx fields and the element states equal the C
!             API's (argv 1, written by transient_language_cases) bitwise,
!             and so do W_slip, each committed step's wear, the work field,
!             the Jacobian of the last trial (jacobian(r, c) = the C API's
!             [3 (r-1) + c-1]), the accumulated wear and its map, and the
!             shift and two steps in world-fixed coordinates
!   CONTACT   the shift and the creepages of cases 2 .. 15 as CONTACT prints
!             them (argv 2: tests/data/transient/catt_to_cart.csv, eve70a/CONTACT
!             d431cdb; %.3E), the adhesion and slip counts
!   state     save after the shift, restore after more steps: the trial again
!             gives the same bits; commit without a trial is CW_ERR_NO_SOLUTION
!   errors    through stat/errmsg, naming the input: dq beyond dx, |Fx| >= mu N,
!             the calibrated model, words of another handle, a field array of the wrong
!             shape, a handle never created, coordinates = 7, world-fixed FASTSIM,
!             a Jacobian without a step, wear law 9, a wear map of the wrong shape;
!             nothing written on error
program test_fortran_transient
   use, intrinsic :: iso_c_binding, only: c_double, c_int, c_int64_t, c_loc, c_size_t
   use creepwork
   use cw_test_support
   implicit none

   integer, parameter :: nx = 34, ny = 33, n_rolling = 14
   real(c_double), parameter :: dx = 0.25e-3_c_double, mu = 0.4013_c_double, load = 0.4705_c_double
   real(c_double), parameter :: mu_n = mu*load
   real(c_double), target :: h(nx, ny)
   character(len=32768) :: line ! one record of the C side: 1122 values of up to 25 characters

   call check_bits(command_argument(1))
   call check_contact(command_argument(2))
   call check_save_restore()
   call check_errors()
   call test_summary('test_fortran_transient')

contains

   ! catt_to_cart's contact: h(i, j) at x0 + (i-1) dx, y0 + (j-1) dx.
   subroutine make(t, grid, p)
      type(cw_transient_type), intent(inout) :: t
      type(cw_grid), intent(out) :: grid
      type(cw_params), intent(out) :: p
      integer :: i, j
      real(c_double) :: x, y
      call cw_grid_init(grid)
      grid%kind = CW_GRID_GAP
      grid%nx = nx
      grid%ny = ny
      grid%x0 = -4e-3_c_double
      grid%y0 = -4e-3_c_double
      grid%dx = dx
      grid%dy = dx
      do j = 1, ny
         do i = 1, nx
            x = grid%x0 + (i - 1)*grid%dx
            y = grid%y0 + (j - 1)*grid%dy
            h(i, j) = 2.963_c_double*(x*x + y*y)
         end do
      end do
      call cw_params_init(p)
      p%model = CW_MODEL_EXACT
      p%normal_force = load
      p%G = 1e6_c_double
      p%nu = 0.28_c_double
      p%mu = mu
      p%gap = c_loc(h)
      p%gap_len = size(h, kind=c_size_t)
      call t%create(grid, p)
   end subroutine make

   function force_step(dq, fx_over_mu_n) result(s)
      real(c_double), intent(in) :: dq, fx_over_mu_n
      type(cw_transient_input) :: s
      call cw_transient_input_init(s)
      s%dq = dq
      s%prescribe = CW_PRESCRIBE_FX
      s%Fx = fx_over_mu_n*mu_n
   end function force_step

   subroutine check_bits(path)
      character(len=*), intent(in) :: path
      type(cw_transient_type) :: t, world
      type(cw_grid) :: grid
      type(cw_params) :: p
      type(cw_transient_input) :: s
      type(cw_transient_result) :: r
      real(c_double) :: c(9), extra(2), field(nx, ny), expected(nx*ny), jac(3, 3), jv(9), mass, m
      real(c_double) :: x(5)
      integer(c_int) :: state(nx, ny)
      integer :: unit, ios, counts(4), id, n, expected_state(nx*ny), n_steps, n_fields, n_world
      integer :: slip, row, col
      character(len=8) :: what
      call make(t, grid, p)
      n_world = 0
      open (newunit=unit, file=path, status='old', action='read', iostat=ios)
      call check_true(ios == 0, 'open '//path)
      if (ios /= 0) return
      n_steps = 0
      n_fields = 0
      do
         read (unit, '(a)', iostat=ios) line
         if (ios /= 0) exit
         select case (line(1:1))
         case ('S')
            read (line(2:), *) c, counts, extra
            n_steps = n_steps + 1
            write (what, '(i0)') n_steps
            s = force_step(c(1), 0.0_c_double)
            s%Fx = c(2)
            if (n_steps == n_rolling + 2) then
               ! the rewound trial of the C side first
               call cw_transient_input_init(s)
               s%dq = dx
               s%xi_x = 1e-3_c_double
               call t%step(s)
               call t%rewind()
               s = force_step(c(1), 0.0_c_double)
               s%Fx = c(2)
            end if
            call cw_transient_result_init(r)
            call t%step(s, r)
            m = 0
            if (n_steps <= n_rolling + 1) then
               call t%commit()
               call t%add_wear(step_mass=m)
            end if
            call check_same(r%W_slip, extra(1), 'step '//trim(what)//' W_slip')
            call check_same(m, extra(2), 'step '//trim(what)//' wear mass')
            call check_same(r%xi_x, c(3), 'step '//trim(what)//' xi_x')
            call check_same(r%xi_y, c(4), 'step '//trim(what)//' xi_y')
            call check_same(r%phi, c(5), 'step '//trim(what)//' phi')
            call check_same(r%Fx, c(6), 'step '//trim(what)//' Fx')
            call check_same(r%Fy, c(7), 'step '//trim(what)//' Fy')
            call check_same(r%Mz, c(8), 'step '//trim(what)//' Mz')
            call check_same(r%W_step, c(9), 'step '//trim(what)//' W_step')
            call check_int(int(r%n_contact), counts(1), 'step '//trim(what)//' n_contact')
            call check_int(int(r%n_adhesion), counts(2), 'step '//trim(what)//' n_adhesion')
            call check_int(int(r%n_slip), counts(3), 'step '//trim(what)//' n_slip')
            call check_int(int(r%iterations), counts(4), 'step '//trim(what)//' iterations')
         case ('F')
            read (line(2:), *) id, n
            call check_int(n, nx*ny, 'field length')
            read (line(2:), *) id, n, expected
            call t%get_field(id, field)
            call check_true(all(reshape(field, [nx*ny]) == expected), 'field '//line(3:4)//' bitwise')
            n_fields = n_fields + 1
         case ('Z')
            read (line(2:), *) n, expected_state
            call t%get_state(state)
            call check_true(all(reshape(state, [nx*ny]) == expected_state), 'element states')
            n_fields = n_fields + 1
         case ('J')
            read (line(2:), *) jv
            call t%jacobian(jac)
            do row = 1, 3
               do col = 1, 3
                  call check_same(jac(row, col), jv(3*(row - 1) + col), 'jacobian')
               end do
            end do
            n_fields = n_fields + 1
         case ('M')
            read (line(2:), *) mass, n, expected
            call t%get_wear(m, field)
            call check_same(m, mass, 'accumulated wear')
            call check_true(all(reshape(field, [nx*ny]) == expected), 'wear map bitwise')
            n_fields = n_fields + 1
         case ('X')
            read (line(2:), *) x, slip
            if (n_world == 0) then
               call make(world, grid, p)
               call world%set_coordinates(CW_COORDINATES_WORLD)
            end if
            n_world = n_world + 1
            s = force_step(x(1), 0.0_c_double)
            s%Fx = x(2)
            call world%step(s, r)
            call world%commit()
            call check_same(r%xi_x, x(3), 'world step xi_x')
            call check_same(r%Fx, x(4), 'world step Fx')
            call check_same(r%W_step, x(5), 'world step W_step')
            call check_int(int(r%n_slip), slip, 'world step n_slip')
         end select
      end do
      close (unit)
      call check_int(n_steps, n_rolling + 2, 'steps read')
      call check_int(n_fields, 6, 'fields, states, Jacobian and wear read')
      call check_int(n_world, 3, 'world-fixed steps read')
      call t%destroy()
      call world%destroy()
   end subroutine check_bits

   ! CONTACT's printed creepage (the shift in mm there) and element counts.
   subroutine check_contact(path)
      character(len=*), intent(in) :: path
      type(cw_transient_type) :: t
      type(cw_grid) :: grid
      type(cw_params) :: p
      type(cw_transient_result) :: r
      character(len=16) :: kind, got, want
      integer :: unit, ios, k, i, n, comma(5), adhesion, slip
      character(len=16) :: case_name
      real(c_double) :: value
      call make(t, grid, p)
      open (newunit=unit, file=path, status='old', action='read', iostat=ios)
      call check_true(ios == 0, 'open '//path)
      if (ios /= 0) return
      read (unit, '(a)') line ! header: case,kind,value,n_adhesion,n_slip,fric
      do k = 1, n_rolling + 1
         read (unit, '(a)') line
         n = 0
         do i = 1, len_trim(line)
            if (line(i:i) == ',' .and. n < 5) then
               n = n + 1
               comma(n) = i
            end if
         end do
         write (case_name, '(a,i0)') 'case ', k
         kind = line(comma(1) + 1:comma(2) - 1)
         want = line(comma(2) + 1:comma(3) - 1)
         read (line(comma(3) + 1:comma(4) - 1), *) adhesion
         read (line(comma(4) + 1:comma(5) - 1), *) slip
         if (trim(kind) == 'shift') then
            call t%step(force_step(0.0_c_double, -0.657_c_double), r)
            value = r%xi_x*1e3_c_double ! CONTACT prints the shift in mm
         else
            call t%step(force_step(dx, -0.657_c_double), r)
            value = r%xi_x
         end if
         call t%commit()
         write (got, '(es10.3e2)') value
         call check_string(trim(adjustl(got)), trim(want), trim(case_name)//' creepage')
         call check_int(int(r%n_adhesion), adhesion, trim(case_name)//' n_adhesion')
         call check_int(int(r%n_slip), slip, trim(case_name)//' n_slip')
         call check_close(r%Fx, -0.657_c_double*mu_n, 0.0_c_double, 1e-8_c_double*mu_n, &
                          trim(case_name)//' Fx met to tolerance mu N')
      end do
      close (unit)
      call t%destroy()
   end subroutine check_contact

   subroutine check_save_restore()
      type(cw_transient_type) :: t
      type(cw_grid) :: grid
      type(cw_params) :: p
      type(cw_transient_result) :: a, b
      integer(c_int64_t), allocatable :: saved(:)
      real(c_double) :: px(nx, ny)
      integer :: stat
      character(len=:), allocatable :: msg
      call make(t, grid, p)
      call t%step(force_step(0.0_c_double, -0.657_c_double))
      call t%commit()
      allocate (saved(t%state_size()))
      call check_true(size(saved) > nx*ny, 'state_size holds the tractions')
      call t%save(saved)
      call t%step(force_step(dx, -0.5_c_double), a)
      call t%get_field(CW_FIELD_PX, px)
      call t%commit()
      call t%step(force_step(dx, -0.5_c_double))
      call t%commit()
      call t%restore(saved)
      call t%commit(stat=stat, errmsg=msg)
      call check_int(stat, CW_ERR_NO_SOLUTION, 'commit after restore: no trial')
      call check_true(index(msg, 'no step to commit') > 0, 'commit names the missing trial: '//msg)
      call t%step(force_step(dx, -0.5_c_double), b)
      call check_same(b%xi_x, a%xi_x, 'restored trial xi_x')
      call check_same(b%Mz, a%Mz, 'restored trial Mz')
      call check_same(b%W_step, a%W_step, 'restored trial W_step')
      call check_int(int(b%steps_committed), 1, 'restored steps_committed')
      ! The traction sums to Fx (the header: creep force on the wheel).
      call check_close(sum(px)*dx*dx, a%Fx, 1e-12_c_double, 0.0_c_double, 'sum px dA = Fx')
      call t%destroy()
   end subroutine check_save_restore

   subroutine check_errors()
      type(cw_transient_type) :: t, never
      type(cw_grid) :: grid
      type(cw_params) :: p
      type(cw_transient_input) :: s
      type(cw_transient_result) :: r
      integer(c_int64_t) :: junk(3)
      real(c_double) :: wrong(ny, nx), jac(3, 3), mass
      type(cw_wear_params) :: law
      integer :: stat
      character(len=:), allocatable :: msg
      call make(t, grid, p)
      call cw_transient_result_init(r)
      r%xi_x = -7.0_c_double
      s = force_step(2*dx, -0.5_c_double)
      call t%step(s, r, stat=stat, errmsg=msg)
      call check_int(stat, CW_ERR_INVALID_INPUT, 'dq = 2 dx refused')
      call check_true(index(msg, 'dq') > 0, 'the message names dq: '//msg)
      call check_same(r%xi_x, -7.0_c_double, 'nothing written on error')
      call t%step(force_step(dx, -1.0_c_double), stat=stat, errmsg=msg)
      call check_int(stat, CW_ERR_INVALID_INPUT, 'Fx = -mu N refused')
      call check_true(index(msg, 'mu N') > 0, 'the message names mu N: '//msg)
      junk = 0
      call t%restore(junk, stat=stat, errmsg=msg)
      call check_int(stat, CW_ERR_INVALID_INPUT, 'foreign words refused')
      call t%step(force_step(0.0_c_double, -0.5_c_double))
      call t%get_field(CW_FIELD_PX, wrong, stat=stat, errmsg=msg)
      call check_int(stat, CW_ERR_INVALID_INPUT, 'a (ny, nx) array refused')
      call check_true(index(msg, '(33, 34)') > 0, 'the message names the shape: '//msg)
      call t%get_wear(mass, wrong, stat=stat, errmsg=msg)
      call check_int(stat, CW_ERR_INVALID_INPUT, 'a (ny, nx) wear map refused')
      call check_true(index(msg, '(33, 34)') > 0, 'the message names the shape: '//msg)
      call cw_wear_params_init(law)
      law%law = 9
      call t%add_wear(law, stat=stat, errmsg=msg)
      call check_int(stat, CW_ERR_UNKNOWN_OPTION, 'wear law 9 refused')
      call check_true(index(msg, 'law') > 0, 'the message names the law: '//msg)
      call t%set_coordinates(7, stat=stat, errmsg=msg)
      call check_int(stat, CW_ERR_UNKNOWN_OPTION, 'coordinates = 7 refused')
      call check_true(index(msg, 'coordinates') > 0, 'the message names coordinates: '//msg)
      call t%start_zero()
      jac = -7.0_c_double
      call t%jacobian(jac, stat=stat, errmsg=msg)
      call check_int(stat, CW_ERR_NO_SOLUTION, 'a Jacobian without a step')
      call check_true(all(jac == -7.0_c_double), 'nothing written on error (Jacobian)')
      call t%reset_wear()
      call t%get_wear(mass)
      call check_same(mass, 0.0_c_double, 'reset_wear clears the mass')
      call t%destroy()
      p%model = CW_MODEL_FASTSIM
      call t%create(grid, p)
      call t%set_coordinates(CW_COORDINATES_WORLD, stat=stat, errmsg=msg)
      call check_int(stat, CW_ERR_INVALID_INPUT, 'world-fixed FASTSIM refused')
      call check_true(index(msg, 'CW_MODEL_FASTSIM') > 0, 'the message names the model: '//msg)
      call t%destroy()
      p%model = CW_MODEL_CALIBRATED
      call t%create(grid, p, stat=stat, errmsg=msg)
      call check_int(stat, CW_ERR_INVALID_INPUT, 'model calibrated refused')
      call check_true(index(msg, 'model') > 0, 'the message names the model: '//msg)
      call check_true(.not. t%is_created(), 'no handle after a refused create')
      call never%step(s, stat=stat, errmsg=msg)
      call check_int(stat, CW_ERR_NULL_POINTER, 'a handle never created')
      call check_true(index(msg, 'transient has not been created') > 0, 'named: '//msg)
      call check_int(never%state_size(), 0, 'state_size before create')
   end subroutine check_errors

end program test_fortran_transient
