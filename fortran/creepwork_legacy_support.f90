! Shared by the legacy routines (creepwork_legacy*.f90), not for callers:
!   the calling thread's last message (CWLAST) and CWFORC's solvers, kept by
!   legacy_thread_state.cpp; the check that rejects subnormal inputs by
!   name; the parameters and the solve of the dimensional entries.
module creepwork_legacy_support
   use, intrinsic :: iso_c_binding, only: c_double, c_int, c_int64_t, c_size_t, c_char
   use creepwork
   use creepwork_handle, only: outcome, make_outcome, integer_text
   implicit none
   private
   public :: legacy_solve, subnormal, flushed, material_params
   public :: check_normal, check_array, check_cells, check_range, remember, remember_error, real_text
   public :: cwl_copy_message, cwl_solve_cached, cwl_free_solvers

   interface
      ! legacy_thread_state.cpp: the calling thread's last message ...
      subroutine cwl_set_message(text, length) bind(c, name='cwl_set_message')
         import :: c_char, c_size_t
         character(kind=c_char), intent(in) :: text(*)
         integer(c_size_t), value :: length
      end subroutine cwl_set_message
      function cwl_copy_message(out, capacity) bind(c, name='cwl_copy_message') result(length)
         import :: c_char, c_size_t
         character(kind=c_char), intent(inout) :: out(*)
         integer(c_size_t), value :: capacity
         integer(c_size_t) :: length
      end function cwl_copy_message
      ! ... and its solvers, one per grid shape (at most 4, the least
      ! recently used freed first): cw_solver_solve on the one for grid,
      ! setting the thread's message.
      function cwl_solve_cached(grid, params, mode, result) bind(c, name='cwl_solve_cached') &
         result(status)
         import :: c_int, cw_grid, cw_params, cw_result
         type(cw_grid), intent(in) :: grid
         type(cw_params), intent(in) :: params
         integer(c_int), value :: mode
         type(cw_result), intent(inout) :: result
         integer(c_int) :: status
      end function cwl_solve_cached
      subroutine cwl_free_solvers() bind(c, name='cwl_free_solvers')
      end subroutine cwl_free_solvers
   end interface

contains

   ! The calling thread's last message := message ('' after a success).
   subroutine remember(message)
      character(len=*), intent(in) :: message
      call cwl_set_message(message, len(message, kind=c_size_t))
   end subroutine remember

   ! ierr := status, and the thread's message "<static message>: detail".
   subroutine remember_error(status, detail, ierr)
      integer(c_int), intent(in) :: status
      character(len=*), intent(in) :: detail
      integer(c_int), intent(out) :: ierr
      type(outcome) :: o
      ierr = status
      o = make_outcome(status, detail)
      call remember(o%message)
   end subroutine remember_error

   ! x is a subnormal number: its exponent bits are zero and it is not zero.
   ! Tested on the bits, so that reading it raises no denormal exception.
   ! No physical input is ~1e-310; the usual cause is a REAL (single
   ! precision) actual argument followed by zero bytes.
   elemental logical function subnormal(x)
      real(c_double), intent(in) :: x
      integer(c_int64_t) :: bits
      bits = transfer(x, bits)
      subnormal = ibits(bits, 52, 11) == 0 .and. ibits(bits, 0, 52) /= 0
   end function subnormal

   ! x cannot be an input of any contact: subnormal, or beyond 1e30 in
   ! magnitude (tested on the exponent bits: no exception even for NaN).
   ! The usual cause is a REAL (single precision) actual argument, whose four
   ! bytes are followed by whatever lies next in memory.
   elemental logical function garbled(x)
      real(c_double), intent(in) :: x
      integer(c_int64_t) :: bits
      integer :: exponent
      bits = transfer(x, bits)
      exponent = ibits(bits, 52, 11)
      ! 2**100 = 1.27e30; 2047 (NaN, Inf) is left to the library's own message
      garbled = subnormal(x) .or. (exponent >= 1023 + 100 .and. exponent < 2047)
   end function garbled

   ! ierr := CW_OK, or CW_ERR_INVALID_INPUT naming the first subnormal or
   ! huge value (garbled); names holds the arguments' names, blank-separated,
   ! in order.
   subroutine check_normal(values, names, ierr)
      real(c_double), intent(in) :: values(:)
      character(len=*), intent(in) :: names
      integer(c_int), intent(out) :: ierr
      integer :: k
      ierr = CW_OK
      if (.not. any(garbled(values))) return
      k = findloc(garbled(values), .true., dim=1)
      if (subnormal(values(k))) then
         call remember_error(CW_ERR_INVALID_INPUT, trim(word(names, k))//' is a subnormal number '// &
                             '(a REAL passed for DOUBLE PRECISION? CWTYPE checks the kinds)', ierr)
      else
         call remember_error(CW_ERR_INVALID_INPUT, trim(word(names, k))//' = '// &
                             trim(real_text(values(k)))//' is beyond 1e30, no input of a contact '// &
                             '(a REAL passed for DOUBLE PRECISION? CWTYPE checks the kinds)', ierr)
      end if
   end subroutine check_normal

   ! With ierr = CW_OK and found (an array holds a subnormal number): ierr
   ! := CW_ERR_INVALID_INPUT naming the array; else nothing. So that after a
   ! run of checks ierr and the message are those of the first failure.
   subroutine check_array(found, name, ierr)
      logical, intent(in) :: found
      character(len=*), intent(in) :: name
      integer(c_int), intent(inout) :: ierr
      if (found .and. ierr == CW_OK) &
         call remember_error(CW_ERR_INVALID_INPUT, name//' holds a subnormal number '// &
                             '(a REAL passed for DOUBLE PRECISION?)', ierr)
   end subroutine check_array

   ! List-directed text of a real, left-adjusted (use it trimmed; no format
   ! string: see integer_text of creepwork_handle.f90).
   function real_text(x) result(s)
      real(c_double), intent(in) :: x
      character(len=40) :: s
      write (s, *) x
      s = adjustl(s)
   end function real_text

   ! The k-th blank-separated word of text ('?' if there are fewer),
   ! blank-padded.
   function word(text, k) result(w)
      character(len=*), intent(in) :: text
      integer, intent(in) :: k
      character(len=len(text)) :: w
      integer :: i, n, start
      n = 0
      start = 0
      do i = 1, len(text) + 1
         if (i <= len(text)) then
            if (text(i:i) /= ' ') then
               if (start == 0) start = i
               cycle
            end if
         end if
         if (start > 0) then
            n = n + 1
            if (n == k) then
               w = text(start:i - 1)
               return
            end if
            start = 0
         end if
      end do
      w = '?'
   end function word

   ! ierr := CW_OK, or status naming the count n outside low..high.
   subroutine check_range(n, name, low, high, status, ierr)
      integer(c_int), intent(in) :: n
      character(len=*), intent(in) :: name
      integer, intent(in) :: low, high
      integer(c_int), intent(in) :: status
      integer(c_int), intent(out) :: ierr
      ierr = CW_OK
      if (n >= low .and. n <= high) return
      call remember_error(status, name//' = '//trim(integer_text(int(n)))//' is outside '// &
                          trim(integer_text(low))//'..'//trim(integer_text(high)), ierr)
   end subroutine check_range

   ! ierr := CW_OK, or CW_ERR_GRID_OUT_OF_RANGE naming the grid dimension
   ! outside 1..CW_MAX_GRID_CELLS.
   subroutine check_cells(n, name, ierr)
      integer(c_int), intent(in) :: n
      character(len=*), intent(in) :: name
      integer(c_int), intent(out) :: ierr
      call check_range(n, name, 1, int(CW_MAX_GRID_CELLS), CW_ERR_GRID_OUT_OF_RANGE, ierr)
   end subroutine check_cells

   ! x, or 0 if it is subnormal (a result the next call would have to read).
   elemental real(c_double) function flushed(x)
      real(c_double), intent(in) :: x
      flushed = x
      if (subnormal(x)) flushed = 0.0_c_double
   end function flushed

   ! The parameters of a dimensional legacy call with flexibilities from G
   ! and PNU (CWSOLM, CWSOLX, CWJACO, CWFORC, CWWEAR): every other field at
   ! its default.
   function material_params(a, b, fn, fmu, g, pnu, xi, eta, phi) result(p)
      real(c_double), intent(in) :: a, b, fn, fmu, g, pnu, xi, eta, phi
      type(cw_params) :: p
      call cw_params_init(p)
      p%a = a
      p%b = b
      p%normal_force = fn
      p%mu = fmu
      p%flexibility = CW_FLEX_FROM_MATERIAL
      p%G = g
      p%nu = pnu
      p%xi_x = xi
      p%xi_y = eta
      p%phi = phi
   end function material_params

   ! Kalker's strip grid, or with box present CONTACT's uniform grid over
   ! [-box a, box a] x [-box b, box b]; pz, pmax, appr (all or none) receive
   ! the pressure map, p_max and the approach.
   subroutine legacy_solve(params, nx, ny, fx, fy, fmz, wmac, wmic, ck, px, py, sx, sy, &
                           zmap, wpap, wcon, istate, ierr, box, pz, pmax, appr)
      type(cw_params), intent(in) :: params
      integer(c_int), intent(in) :: nx, ny
      real(c_double), intent(inout) :: fx, fy, fmz, wmac, wmic, ck
      real(c_double), intent(inout), dimension(nx, ny) :: px, py, sx, sy, zmap, wpap, wcon
      integer(c_int), intent(inout) :: istate(nx, ny)
      integer(c_int), intent(out) :: ierr
      real(c_double), intent(in), optional :: box
      real(c_double), intent(inout), optional :: pz(nx, ny), pmax, appr
      type(cw_solver_type) :: solver
      type(cw_result) :: r
      character(len=:), allocatable :: message
      integer :: stat
      real(c_double) :: box_scale
      box_scale = 1
      if (present(box)) box_scale = box
      call check_normal([params%a, params%b, params%normal_force, params%mu, params%G, params%nu, &
                         params%L1, params%L2, params%L3, params%xi_x, params%xi_y, params%phi, &
                         box_scale], 'A B FN FMU G PNU FL1 FL2 FL3 XI ETA PHI BOX', ierr)
      if (ierr /= CW_OK) return
      if (present(box)) then
         call solver%create(nx=nx, ny=ny, kind=int(CW_GRID_UNIFORM), box_scale=box, stat=stat, &
                            errmsg=message)
      else
         call solver%create(nx=nx, ny=ny, stat=stat, errmsg=message)
      end if
      if (stat == CW_OK) call solver%solve(params, CW_SOLVE_FULL, r, stat=stat, errmsg=message)
      if (stat == CW_OK .and. present(pz)) &
         call solver%get_field(CW_FIELD_PZ, pz, stat=stat, errmsg=message)
      ! After a successful full solve no field can fail; stop at the first
      ! error all the same.
      if (stat == CW_OK) call solver%get_field(CW_FIELD_PX, px, stat=stat, errmsg=message)
      if (stat == CW_OK) call solver%get_field(CW_FIELD_PY, py, stat=stat, errmsg=message)
      if (stat == CW_OK) call solver%get_field(CW_FIELD_SX, sx, stat=stat, errmsg=message)
      if (stat == CW_OK) call solver%get_field(CW_FIELD_SY, sy, stat=stat, errmsg=message)
      if (stat == CW_OK) call solver%get_field(CW_FIELD_MZ, zmap, stat=stat, errmsg=message)
      if (stat == CW_OK) call solver%get_field(CW_FIELD_WORK_PAPER, wpap, stat=stat, errmsg=message)
      if (stat == CW_OK) &
         call solver%get_field(CW_FIELD_WORK_CONSISTENT, wcon, stat=stat, errmsg=message)
      if (stat == CW_OK) call solver%get_state(istate, stat=stat, errmsg=message)
      if (stat == CW_OK) then
         fx = r%Fx
         fy = r%Fy
         fmz = r%Mz
         wmac = r%W_macro
         wmic = r%W_micro_paper
         ck = r%K
         if (present(pmax)) pmax = r%p_max
         if (present(appr)) appr = r%approach
      end if
      ierr = int(stat, c_int)
      call remember(message)
      call solver%destroy()
   end subroutine legacy_solve

end module creepwork_legacy_support
