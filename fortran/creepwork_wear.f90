! Wear (header section "wear", doc/theory/wear.md): a pass is one axle passage
! (rail) or one wheel revolution (wheel); depths per pass [m].
!   cw_wear_type          owns one cw_wear: the wear of a solved contact by
!                         the USFD or Archard law, for one solver grid
!   cw_wear_profile_type  owns one cw_wear_profile: wear depth accumulated
!                         exactly on a host's profile grid over many passes
module creepwork_wear
   use, intrinsic :: iso_c_binding, only: c_int, c_size_t, c_double, c_int64_t, c_char, c_ptr, &
                                          c_null_ptr, c_null_char, c_loc
   use creepwork_types
   use creepwork_capi
   use creepwork_handle
   use creepwork_solver, only: cw_solver_type
   implicit none
   private

   type, public, extends(cw_handle) :: cw_wear_type
   contains
      procedure :: create => wear_create
      procedure :: compute => wear_compute
      procedure, private :: wear_get_field_2d, wear_get_field_1d
      generic :: get_field => wear_get_field_2d, wear_get_field_1d
      procedure, private :: wear_get_regimes_2d, wear_get_regimes_1d
      generic :: get_regimes => wear_get_regimes_2d, wear_get_regimes_1d
      procedure :: get_strips => wear_get_strips
      procedure :: get_result => wear_get_result
      procedure, nopass :: noun => wear_noun
   end type cw_wear_type

   type, public, extends(cw_handle) :: cw_wear_profile_type
   contains
      procedure :: create => profile_create
      procedure :: reset => profile_reset
      procedure :: add => profile_add
      procedure :: add_strips => profile_add_strips
      procedure :: get_depth => profile_get_depth
      procedure :: get_totals => profile_get_totals
      procedure :: merge => profile_merge
      procedure :: state_size => profile_state_size
      procedure :: get_state => profile_get_state
      procedure :: add_state => profile_add_state
      procedure, nopass :: noun => profile_noun
   end type cw_wear_profile_type

contains

   ! ================================================================ wear

   function wear_noun() result(s)
      character(len=noun_length) :: s
      s = 'wear'
   end function wear_noun

   ! Creates the wear workspace for the grid of solver (destroying a
   ! previous one).
   subroutine wear_create(self, solver, stat, errmsg)
      class(cw_wear_type), intent(inout) :: self
      class(cw_solver_type), intent(in) :: solver
      integer, intent(out), optional :: stat
      character(len=:), allocatable, intent(out), optional :: errmsg
      type(c_ptr) :: handle
      integer :: nx, ny
      type(outcome) :: o
      call self%destroy()
      o = created(solver)
      if (o%status == CW_OK) o = make_outcome(capi_wear_create(handle_of(solver), handle), '')
      if (o%status == CW_OK) then
         call grid_of(solver, nx, ny)
         call adopt(self, handle, capi_wear_destroy, capi_wear_last_error, nx, ny)
      end if
      if (present(errmsg)) call set_errmsg(o, errmsg)
      call deliver(o, stat)
   end subroutine wear_create

   ! The wear of solver's last CW_SOLVE_FULL solve. params (default: the
   ! defaults of cw_wear_params_init) and result are optional; an
   ! uninitialised result (struct_size 0) is initialised first.
   subroutine wear_compute(self, solver, params, result, stat, errmsg)
      class(cw_wear_type), intent(inout) :: self
      class(cw_solver_type), intent(in) :: solver
      type(cw_wear_params), intent(in), optional :: params
      type(cw_wear_result), intent(inout), target, optional :: result
      integer, intent(out), optional :: stat
      character(len=:), allocatable, intent(out), optional :: errmsg
      type(cw_wear_params) :: p
      type(c_ptr) :: pr
      integer(c_int) :: status
      type(outcome) :: o
      o = created(self)
      if (o%status == CW_OK) o = created(solver)
      if (o%status == CW_OK) then
         if (present(params)) then
            p = params
         else
            status = capi_wear_params_init(p)
         end if
         pr = c_null_ptr
         if (present(result)) then
            if (result%struct_size == 0) status = capi_wear_result_init(result)
            pr = c_loc(result)
         end if
         o = status_outcome(self, capi_wear_compute(handle_of(self), handle_of(solver), p, pr))
      end if
      if (present(errmsg)) call set_errmsg(o, errmsg)
      call deliver(o, stat)
   end subroutine wear_compute

   ! A CW_WEAR_FIELD_* of the last compute into out(nx, ny).
   subroutine wear_get_field_2d(self, field, out, stat, errmsg)
      class(cw_wear_type), intent(in) :: self
      integer, intent(in) :: field
      real(c_double), intent(inout), contiguous :: out(:, :)
      integer, intent(out), optional :: stat
      character(len=:), allocatable, intent(out), optional :: errmsg
      type(outcome) :: o
      o = created_map(self, shape(out))
      if (o%status == CW_OK) o = status_outcome(self, capi_wear_get_field( &
                                 handle_of(self), int(field, c_int), out, size(out, kind=c_size_t)))
      if (present(errmsg)) call set_errmsg(o, errmsg)
      call deliver(o, stat)
   end subroutine wear_get_field_2d

   subroutine wear_get_field_1d(self, field, out, stat, errmsg)
      class(cw_wear_type), intent(in) :: self
      integer, intent(in) :: field
      real(c_double), intent(inout), contiguous :: out(:)
      integer, intent(out), optional :: stat
      character(len=:), allocatable, intent(out), optional :: errmsg
      type(outcome) :: o
      o = created(self)
      if (o%status == CW_OK) o = status_outcome(self, capi_wear_get_field( &
                                 handle_of(self), int(field, c_int), out, size(out, kind=c_size_t)))
      if (present(errmsg)) call set_errmsg(o, errmsg)
      call deliver(o, stat)
   end subroutine wear_get_field_1d

   ! CW_WEAR_REGIME_* per element into out(nx, ny).
   subroutine wear_get_regimes_2d(self, out, stat, errmsg)
      class(cw_wear_type), intent(in) :: self
      integer(c_int), intent(inout), contiguous :: out(:, :)
      integer, intent(out), optional :: stat
      character(len=:), allocatable, intent(out), optional :: errmsg
      type(outcome) :: o
      o = created_map(self, shape(out))
      if (o%status == CW_OK) o = status_outcome(self, capi_wear_get_regimes( &
                                 handle_of(self), out, size(out, kind=c_size_t)))
      if (present(errmsg)) call set_errmsg(o, errmsg)
      call deliver(o, stat)
   end subroutine wear_get_regimes_2d

   subroutine wear_get_regimes_1d(self, out, stat, errmsg)
      class(cw_wear_type), intent(in) :: self
      integer(c_int), intent(inout), contiguous :: out(:)
      integer, intent(out), optional :: stat
      character(len=:), allocatable, intent(out), optional :: errmsg
      type(outcome) :: o
      o = created(self)
      if (o%status == CW_OK) o = status_outcome(self, capi_wear_get_regimes( &
                                 handle_of(self), out, size(out, kind=c_size_t)))
      if (present(errmsg)) call set_errmsg(o, errmsg)
      call deliver(o, stat)
   end subroutine wear_get_regimes_1d

   ! The lateral wear profile per strip j = 1..ny: centre y [m], width [m],
   ! depth per pass [m] and the equal-volume parabola [m]; each optional,
   ! each at least ny long.
   subroutine wear_get_strips(self, y, width, depth, parabola, stat, errmsg)
      class(cw_wear_type), intent(in) :: self
      real(c_double), intent(inout), contiguous, target, optional :: y(:), width(:), depth(:), &
                                                                     parabola(:)
      integer, intent(out), optional :: stat
      character(len=:), allocatable, intent(out), optional :: errmsg
      type(c_ptr) :: py, pw, pd, pp
      integer :: nx, ny
      integer(c_size_t) :: n
      type(outcome) :: o
      call grid_of(self, nx, ny)
      n = int(ny, c_size_t)
      py = c_null_ptr
      pw = c_null_ptr
      pd = c_null_ptr
      pp = c_null_ptr
      if (present(y)) call point_at(y, py, n)
      if (present(width)) call point_at(width, pw, n)
      if (present(depth)) call point_at(depth, pd, n)
      if (present(parabola)) call point_at(parabola, pp, n)
      o = created(self)
      if (o%status == CW_OK) o = status_outcome(self, capi_wear_get_strips(handle_of(self), &
                                                                           py, pw, pd, pp, n))
      if (present(errmsg)) call set_errmsg(o, errmsg)
      call deliver(o, stat)
   end subroutine wear_get_strips

   ! Totals of the last compute; an uninitialised result is initialised first.
   subroutine wear_get_result(self, result, stat, errmsg)
      class(cw_wear_type), intent(in) :: self
      type(cw_wear_result), intent(inout) :: result
      integer, intent(out), optional :: stat
      character(len=:), allocatable, intent(out), optional :: errmsg
      type(outcome) :: o
      integer(c_int) :: status
      o = created(self)
      if (o%status == CW_OK) then
         if (result%struct_size == 0) status = capi_wear_result_init(result)
         o = status_outcome(self, capi_wear_get_result(handle_of(self), result))
      end if
      if (present(errmsg)) call set_errmsg(o, errmsg)
      call deliver(o, stat)
   end subroutine wear_get_result

   ! ====================================================== wear profile

   function profile_noun() result(s)
      character(len=noun_length) :: s
      s = 'wear profile'
   end function profile_noun

   ! Creates a profile accumulator on the nodes s [m] (strictly increasing,
   ! at least 2), destroying a previous one.
   subroutine profile_create(self, s, stat, errmsg)
      class(cw_wear_profile_type), intent(inout) :: self
      real(c_double), intent(in), contiguous :: s(:)
      integer, intent(out), optional :: stat
      character(len=:), allocatable, intent(out), optional :: errmsg
      character(kind=c_char) :: buffer(message_capacity)
      type(c_ptr) :: handle
      type(outcome) :: o
      call self%destroy()
      buffer(1) = c_null_char
      o = buffer_outcome(capi_wear_profile_create(s, size(s, kind=c_size_t), handle, buffer, &
                                                size(buffer, kind=c_size_t)), buffer)
      if (o%status == CW_OK) call adopt(self, handle, capi_wear_profile_destroy, &
                                        capi_wear_profile_last_error, size(s), 1)
      if (present(errmsg)) call set_errmsg(o, errmsg)
      call deliver(o, stat)
   end subroutine profile_create

   subroutine profile_reset(self, stat, errmsg)
      class(cw_wear_profile_type), intent(inout) :: self
      integer, intent(out), optional :: stat
      character(len=:), allocatable, intent(out), optional :: errmsg
      type(outcome) :: o
      o = created(self)
      if (o%status == CW_OK) o = status_outcome(self, capi_wear_profile_reset(handle_of(self)))
      if (present(errmsg)) call set_errmsg(o, errmsg)
      call deliver(o, stat)
   end subroutine profile_reset

   ! Adds passes (default 1) times the last compute of wear, its patch
   ! centre at s0 [m]; orientation +1 (default) or -1, contact_angle [rad]
   ! (default 0). See cw_wear_profile_add.
   subroutine profile_add(self, wear, s0, orientation, contact_angle, passes, stat, errmsg)
      class(cw_wear_profile_type), intent(inout) :: self
      class(cw_wear_type), intent(in) :: wear
      real(c_double), intent(in) :: s0
      integer, intent(in), optional :: orientation
      real(c_double), intent(in), optional :: contact_angle, passes
      integer, intent(out), optional :: stat
      character(len=:), allocatable, intent(out), optional :: errmsg
      type(outcome) :: o
      o = created(self)
      if (o%status == CW_OK) o = created(wear)
      if (o%status == CW_OK) o = status_outcome(self, capi_wear_profile_add( &
                                 handle_of(self), handle_of(wear), s0, int_or(orientation, 1_c_int), &
                                 real_or(contact_angle, 0.0_c_double), real_or(passes, 1.0_c_double)))
      if (present(errmsg)) call set_errmsg(o, errmsg)
      call deliver(o, stat)
   end subroutine profile_add

   ! The same from the caller's strips y, width, depth (same size).
   subroutine profile_add_strips(self, y, width, depth, s0, orientation, contact_angle, passes, &
                                 stat, errmsg)
      class(cw_wear_profile_type), intent(inout) :: self
      real(c_double), intent(in), contiguous :: y(:), width(:), depth(:)
      real(c_double), intent(in) :: s0
      integer, intent(in), optional :: orientation
      real(c_double), intent(in), optional :: contact_angle, passes
      integer, intent(out), optional :: stat
      character(len=:), allocatable, intent(out), optional :: errmsg
      type(outcome) :: o
      o = created(self)
      if (o%status == CW_OK .and. (size(width) /= size(y) .or. size(depth) /= size(y))) &
         o = make_outcome(CW_ERR_INVALID_INPUT, 'y, width and depth have sizes '// &
                          trim(integer_text(size(y)))//', '//trim(integer_text(size(width)))// &
                          ', '//trim(integer_text(size(depth)))//': they must be equal')
      if (o%status == CW_OK) o = status_outcome(self, capi_wear_profile_add_strips( &
                                 handle_of(self), y, width, depth, size(y, kind=c_size_t), s0, &
                                 int_or(orientation, 1_c_int), real_or(contact_angle, 0.0_c_double), &
                                 real_or(passes, 1.0_c_double)))
      if (present(errmsg)) call set_errmsg(o, errmsg)
      call deliver(o, stat)
   end subroutine profile_add_strips

   ! Accumulated depth per node [m] (kind CW_WEAR_DEPTH_NORMAL or _HEIGHT).
   subroutine profile_get_depth(self, kind, out, stat, errmsg)
      class(cw_wear_profile_type), intent(in) :: self
      integer, intent(in) :: kind
      real(c_double), intent(inout), contiguous :: out(:)
      integer, intent(out), optional :: stat
      character(len=:), allocatable, intent(out), optional :: errmsg
      type(outcome) :: o
      o = created(self)
      if (o%status == CW_OK) o = status_outcome(self, capi_wear_profile_get_depth( &
                                 handle_of(self), int(kind, c_int), out, size(out, kind=c_size_t)))
      if (present(errmsg)) call set_errmsg(o, errmsg)
      call deliver(o, stat)
   end subroutine profile_get_depth

   subroutine profile_get_totals(self, totals, stat, errmsg)
      class(cw_wear_profile_type), intent(in) :: self
      type(cw_wear_profile_totals), intent(inout) :: totals
      integer, intent(out), optional :: stat
      character(len=:), allocatable, intent(out), optional :: errmsg
      type(outcome) :: o
      integer(c_int) :: status
      o = created(self)
      if (o%status == CW_OK) then
         if (totals%struct_size == 0) status = capi_wear_profile_totals_init(totals)
         o = status_outcome(self, capi_wear_profile_get_totals(handle_of(self), totals))
      end if
      if (present(errmsg)) call set_errmsg(o, errmsg)
      call deliver(o, stat)
   end subroutine profile_get_totals

   ! self += from (same nodes), exactly.
   subroutine profile_merge(self, from, stat, errmsg)
      class(cw_wear_profile_type), intent(inout) :: self
      class(cw_wear_profile_type), intent(in) :: from
      integer, intent(out), optional :: stat
      character(len=:), allocatable, intent(out), optional :: errmsg
      type(outcome) :: o
      o = created(self)
      if (o%status == CW_OK) o = created(from)
      if (o%status == CW_OK) o = status_outcome(self, capi_wear_profile_merge(handle_of(self), &
                                                                              handle_of(from)))
      if (present(errmsg)) call set_errmsg(o, errmsg)
      call deliver(o, stat)
   end subroutine profile_merge

   ! Number of 64-bit words of the exact state (0 if not created).
   integer function profile_state_size(self)
      class(cw_wear_profile_type), intent(in) :: self
      integer(c_size_t) :: words
      profile_state_size = 0
      words = 0
      if (self%is_created()) then
         if (capi_wear_profile_state_size(handle_of(self), words) == CW_OK) &
            profile_state_size = int(words)
      end if
   end function profile_state_size

   ! The exact state into state(1:state_size()), e.g. for MPI.
   subroutine profile_get_state(self, state, stat, errmsg)
      class(cw_wear_profile_type), intent(in) :: self
      integer(c_int64_t), intent(inout), contiguous :: state(:)
      integer, intent(out), optional :: stat
      character(len=:), allocatable, intent(out), optional :: errmsg
      type(outcome) :: o
      o = created(self)
      if (o%status == CW_OK) o = status_outcome(self, capi_wear_profile_get_state( &
                                 handle_of(self), state, size(state, kind=c_size_t)))
      if (present(errmsg)) call set_errmsg(o, errmsg)
      call deliver(o, stat)
   end subroutine profile_get_state

   ! Adds a state saved from an accumulator on the same nodes.
   subroutine profile_add_state(self, state, stat, errmsg)
      class(cw_wear_profile_type), intent(inout) :: self
      integer(c_int64_t), intent(in), contiguous :: state(:)
      integer, intent(out), optional :: stat
      character(len=:), allocatable, intent(out), optional :: errmsg
      type(outcome) :: o
      o = created(self)
      if (o%status == CW_OK) o = status_outcome(self, capi_wear_profile_add_state( &
                                 handle_of(self), state, size(state, kind=c_size_t)))
      if (present(errmsg)) call set_errmsg(o, errmsg)
      call deliver(o, stat)
   end subroutine profile_add_state

   ! An optional real argument, or its default.
   real(c_double) function real_or(value, default)
      real(c_double), intent(in), optional :: value
      real(c_double), intent(in) :: default
      real_or = default
      if (present(value)) real_or = value
   end function real_or

end module creepwork_wear
