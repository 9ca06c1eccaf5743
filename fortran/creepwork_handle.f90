! What every wrapper of module creepwork shares:
!   outcome     the status and message of a call, delivered at the end of
!               every public procedure by the same two lines
!                  if (present(errmsg)) call set_errmsg(o, errmsg)
!                  call deliver(o, stat)
!               (errmsg is passed on only when present: gfortran 12 passes
!               an optional deferred-length dummy on to another optional one
!               with its length lost);
!   cw_handle   the base of the five wrapper types that own a C handle:
!               the pointer, the grid it was made for, and the C functions
!               that free it and give its last message, so that destroy,
!               is_created, last_error, the copy guard and the final safety
!               net are written once;
!   helpers     C strings to Fortran, grid settings, shape checks.
! Internal to the library: module creepwork re-exports none of it.
!
! No procedure of the library calls a function whose result is a
! deferred-length character: gfortran 12 keeps the length of such a result
! in a static variable at the call site, so two threads calling it at once
! race (and may copy past a buffer). Strings come back through subroutine
! arguments or fixed-length results instead; check_fortran_static_data
! looks for such statics in the library.
module creepwork_handle
   use, intrinsic :: iso_c_binding, only: c_int, c_size_t, c_double, c_char, c_ptr, c_null_ptr, &
                                          c_null_char, c_associated, c_f_pointer, c_loc
   use creepwork_types
   use creepwork_capi, only: c_strlen, capi_status_string, capi_grid_init
   implicit none
   private
   public :: outcome, make_outcome, buffer_outcome, set_errmsg, deliver, c_text, integer_text
   public :: buffer_text, c_chars
   public :: message_capacity, make_grid, int_or, point_at
   public :: cw_handle, adopt, handle_of, grid_of, created, created_map, status_outcome

   ! Size of the message buffers handed to the C functions that take one.
   integer, parameter :: message_capacity = 1024
   ! Length of the result of noun().
   integer, parameter, public :: noun_length = 16

   ! Status and message of a call: message is "<static message>: <detail>"
   ! on error and left unallocated on success, so that a successful call in
   ! a time loop allocates nothing.
   type :: outcome
      integer(c_int) :: status = CW_OK
      character(len=:), allocatable :: message
   end type outcome

   ! The C functions every handle has: cw_x_destroy and cw_x_last_error.
   abstract interface
      function c_destroy_function(handle) bind(c) result(status)
         import :: c_ptr, c_int
         type(c_ptr), value :: handle
         integer(c_int) :: status
      end function c_destroy_function
      function c_message_function(handle) bind(c) result(message)
         import :: c_ptr
         type(c_ptr), value :: handle
         type(c_ptr) :: message
      end function c_message_function
   end interface

   ! Owns one C handle. Each extension sets it with adopt in its create and
   ! names itself with noun; everything else is shared. An explicit,
   ! idempotent destroy; the final procedure is only a safety net (gfortran
   ! 12 does not finalize reliably); copying a live handle is an error.
   type, public :: cw_handle
      private
      type(c_ptr) :: ptr = c_null_ptr
      integer :: nx = 0, ny = 0 ! the grid (or nodes and 1) it was made for; 0 before create
      procedure(c_destroy_function), pointer, nopass :: c_destroy => null()
      procedure(c_message_function), pointer, nopass :: c_last_error => null()
   contains
      procedure :: destroy => handle_destroy
      procedure :: is_created => handle_is_created
      procedure :: last_error => handle_last_error
      procedure, nopass :: noun => handle_noun
      procedure, private :: handle_assign
      generic :: assignment(=) => handle_assign
      final :: handle_finalize
   end type cw_handle

contains

   ! ============================================================ outcomes

   ! Outcome of a status with "<static message>: <detail>" (or the static
   ! message alone); success carries no message.
   function make_outcome(status, detail) result(o)
      integer(c_int), intent(in) :: status
      character(len=*), intent(in) :: detail
      type(outcome) :: o
      character(len=:), allocatable :: head
      o%status = status
      if (status /= CW_OK) then
         call c_text(capi_status_string(status), head)
         if (len(detail) > 0) then
            o%message = head//': '//detail
         else
            o%message = head
         end if
      end if
   end function make_outcome

   ! make_outcome with the detail a C function wrote into a message buffer.
   function buffer_outcome(status, buffer) result(o)
      integer(c_int), intent(in) :: status
      character(kind=c_char), intent(in) :: buffer(:)
      type(outcome) :: o
      character(len=:), allocatable :: detail
      call buffer_text(buffer, detail)
      o = make_outcome(status, detail)
   end function buffer_outcome

   ! errmsg := '' on success, else the message.
   subroutine set_errmsg(o, errmsg)
      type(outcome), intent(in) :: o
      character(len=:), allocatable, intent(out) :: errmsg
      if (allocated(o%message)) then
         errmsg = o%message
      else
         errmsg = ''
      end if
   end subroutine set_errmsg

   ! The status to stat when present; otherwise an error stops the program
   ! with the message (success does nothing).
   subroutine deliver(o, stat)
      type(outcome), intent(in) :: o
      integer, intent(out), optional :: stat
      if (present(stat)) stat = int(o%status)
      if (o%status /= CW_OK .and. .not. present(stat)) then
         error stop 'creepwork: '//o%message
      end if
   end subroutine deliver

   ! ============================================================ strings

   ! s := copy of the NUL-terminated C string p ('' for NULL).
   subroutine c_text(p, s)
      type(c_ptr), intent(in) :: p
      character(len=:), allocatable, intent(out) :: s
      character(kind=c_char), pointer :: chars(:)
      integer :: n, i
      if (.not. c_associated(p)) then
         s = ''
         return
      end if
      n = int(c_strlen(p))
      call c_f_pointer(p, chars, [n])
      allocate (character(len=n) :: s)
      do i = 1, n
         s(i:i) = chars(i)
      end do
   end subroutine c_text

   ! text as a NUL-terminated C string (trailing blanks dropped).
   function c_chars(text) result(c)
      character(len=*), intent(in) :: text
      character(kind=c_char) :: c(len_trim(text) + 1)
      integer :: i
      do i = 1, len_trim(text)
         c(i) = text(i:i)
      end do
      c(len_trim(text) + 1) = c_null_char
   end function c_chars

   ! s := the text of a message buffer filled by C, up to its NUL.
   subroutine buffer_text(buffer, s)
      character(kind=c_char), intent(in) :: buffer(:)
      character(len=:), allocatable, intent(out) :: s
      integer :: n, i
      n = 0
      do while (n < size(buffer))
         if (buffer(n + 1) == c_null_char) exit
         n = n + 1
      end do
      allocate (character(len=n) :: s)
      do i = 1, n
         s(i:i) = buffer(i)
      end do
   end subroutine buffer_text

   ! Decimal text of an integer, left-adjusted (use it trimmed).
   ! List-directed, so that no format string is parsed: libgfortran copies
   ! formats with strndup, which AddressSanitizer's strict_string_checks
   ! reports as an overflow.
   function integer_text(n) result(s)
      integer, intent(in) :: n
      character(len=24) :: s
      write (s, *) n
      s = adjustl(s)
   end function integer_text

   ! ============================================================ arguments

   ! The grid of the create procedures: grid if given (after cw_grid_init),
   ! else the defaults; nx, ny, kind, box_scale override.
   function make_grid(grid, nx, ny, kind, box_scale) result(g)
      type(cw_grid), intent(in), optional :: grid
      integer, intent(in), optional :: nx, ny, kind
      real(c_double), intent(in), optional :: box_scale
      type(cw_grid) :: g
      integer(c_int) :: status
      if (present(grid)) then
         g = grid
      else
         status = capi_grid_init(g)
      end if
      if (present(nx)) g%nx = int(nx, c_int)
      if (present(ny)) g%ny = int(ny, c_int)
      if (present(kind)) g%kind = int(kind, c_int)
      if (present(box_scale)) g%box_scale = box_scale
   end function make_grid

   ! An optional integer argument, or its default.
   integer(c_int) function int_or(value, default)
      integer, intent(in), optional :: value
      integer(c_int), intent(in) :: default
      int_or = default
      if (present(value)) int_or = int(value, c_int)
   end function int_or

   ! One of several output vectors a C function takes with one length (each
   ! may be NULL there): p points at x, and n falls to its size if that is
   ! shorter. Called only for a present x: an absent optional array passed
   ! on makes gfortran's -fsanitize=undefined report a null load.
   subroutine point_at(x, p, n)
      real(c_double), intent(inout), contiguous, target :: x(:)
      type(c_ptr), intent(out) :: p
      integer(c_size_t), intent(inout) :: n
      p = c_loc(x)
      n = min(n, size(x, kind=c_size_t))
   end subroutine point_at

   ! ============================================================ handles

   ! Gives self the C handle just created, the C functions that free it and
   ! report on it, and its grid (nx, ny) or nodes (n, 1).
   subroutine adopt(self, handle, c_destroy, c_last_error, nx, ny)
      class(cw_handle), intent(inout) :: self
      type(c_ptr), intent(in) :: handle
      procedure(c_destroy_function) :: c_destroy
      procedure(c_message_function) :: c_last_error
      integer, intent(in) :: nx, ny
      self%ptr = handle
      self%c_destroy => c_destroy
      self%c_last_error => c_last_error
      self%nx = nx
      self%ny = ny
   end subroutine adopt

   ! The C handle (NULL before create), for the C calls of the wrappers.
   type(c_ptr) function handle_of(self)
      class(cw_handle), intent(in) :: self
      handle_of = self%ptr
   end function handle_of

   ! The grid self was made for (0, 0 before create).
   subroutine grid_of(self, nx, ny)
      class(cw_handle), intent(in) :: self
      integer, intent(out) :: nx, ny
      nx = self%nx
      ny = self%ny
   end subroutine grid_of

   ! Success, or the error of a call on an object never created.
   function created(self) result(o)
      class(cw_handle), intent(in) :: self
      type(outcome) :: o
      if (.not. c_associated(self%ptr)) &
         o = make_outcome(CW_ERR_NULL_POINTER, 'the '//trim(self%noun())//' has not been '// &
                          'created (call create first)')
   end function created

   ! created, and a caller's map of shape out_shape must be the grid's:
   ! fewer elements is CW_ERR_BUFFER_TOO_SMALL, another shape
   ! CW_ERR_INVALID_INPUT.
   function created_map(self, out_shape) result(o)
      class(cw_handle), intent(in) :: self
      integer, intent(in) :: out_shape(2)
      type(outcome) :: o
      character(len=:), allocatable :: detail
      o = created(self)
      if (o%status /= CW_OK .or. all(out_shape == [self%nx, self%ny])) return
      detail = 'out has shape ('//trim(integer_text(out_shape(1)))//', '// &
               trim(integer_text(out_shape(2)))//') but the grid is ('// &
               trim(integer_text(self%nx))//', '//trim(integer_text(self%ny))//')'
      if (product(out_shape) < self%nx*self%ny) then
         o = make_outcome(CW_ERR_BUFFER_TOO_SMALL, detail)
      else
         o = make_outcome(CW_ERR_INVALID_INPUT, detail)
      end if
   end function created_map

   ! Outcome of a C call on self, with the handle's detailed message.
   function status_outcome(self, status) result(o)
      class(cw_handle), intent(in) :: self
      integer(c_int), intent(in) :: status
      type(outcome) :: o
      character(len=:), allocatable :: detail
      if (status == CW_OK) then
         o%status = status
      else
         call c_text(self%c_last_error(self%ptr), detail)
         o = make_outcome(status, detail)
      end if
   end function status_outcome

   ! Frees the C object; does nothing when there is none (idempotent).
   subroutine handle_destroy(self)
      class(cw_handle), intent(inout) :: self
      integer(c_int) :: status
      if (c_associated(self%ptr)) status = self%c_destroy(self%ptr)
      self%ptr = c_null_ptr
      self%nx = 0
      self%ny = 0
   end subroutine handle_destroy

   logical function handle_is_created(self)
      class(cw_handle), intent(in) :: self
      handle_is_created = c_associated(self%ptr)
   end function handle_is_created

   ! Detailed message of the last error on this object ('' after success).
   function handle_last_error(self) result(s)
      class(cw_handle), intent(in) :: self
      character(len=:), allocatable :: s
      if (c_associated(self%ptr)) then
         call c_text(self%c_last_error(self%ptr), s)
      else
         s = 'the '//trim(self%noun())//' has not been created'
      end if
   end function handle_last_error

   ! What the object is, in messages ("the solver has not been created"),
   ! blank-padded; each extension overrides it.
   function handle_noun() result(s)
      character(len=noun_length) :: s
      s = 'object'
   end function handle_noun

   ! An object owns a C handle: copying a live one would free it twice.
   subroutine handle_assign(lhs, rhs)
      class(cw_handle), intent(inout) :: lhs
      class(cw_handle), intent(in) :: rhs
      character(len=:), allocatable :: message
      if (c_associated(rhs%ptr)) then
         message = 'creepwork: a cw_'//underscored(trim(rhs%noun()))//'_type cannot be '// &
                   'copied (pass it by reference)'
         error stop message
      end if
      call lhs%destroy()
   end subroutine handle_assign

   function underscored(words) result(s)
      character(len=*), intent(in) :: words
      character(len=len(words)) :: s
      integer :: i
      s = words
      do i = 1, len(s)
         if (s(i:i) == ' ') s(i:i) = '_'
      end do
   end function underscored

   subroutine handle_finalize(self)
      type(cw_handle), intent(inout) :: self
      call self%destroy()
   end subroutine handle_finalize

end module creepwork_handle
