! cw_transient_type: owns one cw_transient -- transient rolling in Kalker's
! exact theory or FASTSIM's transient form on a gap grid or an ellipse's
! uniform grid (header section "transient rolling",
! doc/theory/transient.md). create solves the normal problem and starts from
! zero tractions; step computes a trial from the committed state, commit
! makes it the state, rewind drops it; save and restore give and take the
! committed state as 64-bit words. The _init procedures of its structs are
! here (the C ones fail only on a NULL pointer, which a Fortran argument
! cannot be).
module creepwork_transient
   use, intrinsic :: iso_c_binding, only: c_int, c_int64_t, c_size_t, c_double, c_char, c_ptr, &
                                          c_null_char, c_null_ptr, c_loc
   use creepwork_types
   use creepwork_capi
   use creepwork_handle
   implicit none
   private
   public :: cw_transient_input_init, cw_transient_result_init

   type, public, extends(cw_handle) :: cw_transient_type
   contains
      procedure :: create => transient_create
      procedure :: start_zero => transient_start_zero
      procedure :: start_steady => transient_start_steady
      procedure :: step => transient_step
      procedure :: commit => transient_commit
      procedure :: rewind => transient_rewind
      procedure :: state_size => transient_state_size
      procedure :: save => transient_save
      procedure :: restore => transient_restore
      procedure, private :: transient_get_field_2d, transient_get_field_1d
      generic :: get_field => transient_get_field_2d, transient_get_field_1d
      procedure, private :: transient_get_state_2d, transient_get_state_1d
      generic :: get_state => transient_get_state_2d, transient_get_state_1d
      procedure :: set_coordinates => transient_set_coordinates
      procedure :: jacobian => transient_jacobian
      procedure :: add_wear => transient_add_wear
      procedure :: get_wear => transient_get_wear
      procedure :: reset_wear => transient_reset_wear
      procedure, nopass :: noun => transient_noun
   end type cw_transient_type

contains

   subroutine cw_transient_input_init(step)
      type(cw_transient_input), intent(out) :: step
      integer(c_int) :: status
      status = capi_transient_input_init(step)
   end subroutine cw_transient_input_init

   subroutine cw_transient_result_init(result)
      type(cw_transient_result), intent(out) :: result
      integer(c_int) :: status
      status = capi_transient_result_init(result)
   end subroutine cw_transient_result_init

   function transient_noun() result(s)
      character(len=noun_length) :: s
      s = 'transient'
   end function transient_noun

   ! Creates the transient contact of grid (CW_GRID_GAP with p%gap = c_loc(h),
   ! h(nx, ny); or CW_GRID_UNIFORM with the semi-axes p%a, p%b) and params
   ! (model CW_MODEL_EXACT or CW_MODEL_FASTSIM), destroying a previous one:
   ! solves the normal problem, starts from zero tractions.
   subroutine transient_create(self, grid, params, stat, errmsg)
      class(cw_transient_type), intent(inout) :: self
      type(cw_grid), intent(in) :: grid
      type(cw_params), intent(in) :: params
      integer, intent(out), optional :: stat
      character(len=:), allocatable, intent(out), optional :: errmsg
      character(kind=c_char) :: buffer(message_capacity)
      type(c_ptr) :: handle
      integer(c_int) :: status
      type(outcome) :: o
      call self%destroy()
      buffer(1) = c_null_char
      status = capi_transient_create(grid, params, handle, buffer, size(buffer, kind=c_size_t))
      if (status == CW_OK) call adopt(self, handle, capi_transient_destroy, &
                                      capi_transient_last_error, int(grid%nx), int(grid%ny))
      o = buffer_outcome(status, buffer)
      if (present(errmsg)) call set_errmsg(o, errmsg)
      call deliver(o, stat)
   end subroutine transient_create

   ! Starts from zero tractions (no committed step).
   subroutine transient_start_zero(self, stat, errmsg)
      class(cw_transient_type), intent(inout) :: self
      integer, intent(out), optional :: stat
      character(len=:), allocatable, intent(out), optional :: errmsg
      type(outcome) :: o
      o = created(self)
      if (o%status == CW_OK) o = status_outcome(self, capi_transient_start_zero(handle_of(self)))
      if (present(errmsg)) call set_errmsg(o, errmsg)
      call deliver(o, stat)
   end subroutine transient_start_zero

   ! Starts from the steady-rolling solution of step's creepages or forces
   ! (step%dq is not read); result (optional) receives its totals.
   subroutine transient_start_steady(self, step, result, stat, errmsg)
      class(cw_transient_type), intent(inout) :: self
      type(cw_transient_input), intent(in) :: step
      type(cw_transient_result), intent(inout), optional :: result
      integer, intent(out), optional :: stat
      character(len=:), allocatable, intent(out), optional :: errmsg
      type(cw_transient_result) :: r
      type(outcome) :: o
      o = created(self)
      if (o%status == CW_OK) then
         call cw_transient_result_init(r)
         o = status_outcome(self, capi_transient_start_steady(handle_of(self), step, r))
         if (o%status == CW_OK .and. present(result)) result = r
      end if
      if (present(errmsg)) call set_errmsg(o, errmsg)
      call deliver(o, stat)
   end subroutine transient_start_steady

   ! One step from the committed state (a trial): repeated after rewind it
   ! gives the same bits. result (optional) receives the step's totals.
   subroutine transient_step(self, step, result, stat, errmsg)
      class(cw_transient_type), intent(inout) :: self
      type(cw_transient_input), intent(in) :: step
      type(cw_transient_result), intent(inout), optional :: result
      integer, intent(out), optional :: stat
      character(len=:), allocatable, intent(out), optional :: errmsg
      type(cw_transient_result) :: r
      type(outcome) :: o
      o = created(self)
      if (o%status == CW_OK) then
         call cw_transient_result_init(r)
         o = status_outcome(self, capi_transient_step(handle_of(self), step, r))
         if (o%status == CW_OK .and. present(result)) result = r
      end if
      if (present(errmsg)) call set_errmsg(o, errmsg)
      call deliver(o, stat)
   end subroutine transient_step

   ! Makes the last trial the committed state (CW_ERR_NO_SOLUTION without one).
   subroutine transient_commit(self, stat, errmsg)
      class(cw_transient_type), intent(inout) :: self
      integer, intent(out), optional :: stat
      character(len=:), allocatable, intent(out), optional :: errmsg
      type(outcome) :: o
      o = created(self)
      if (o%status == CW_OK) o = status_outcome(self, capi_transient_commit(handle_of(self)))
      if (present(errmsg)) call set_errmsg(o, errmsg)
      call deliver(o, stat)
   end subroutine transient_commit

   ! Drops the last trial; the committed state stays.
   subroutine transient_rewind(self, stat, errmsg)
      class(cw_transient_type), intent(inout) :: self
      integer, intent(out), optional :: stat
      character(len=:), allocatable, intent(out), optional :: errmsg
      type(outcome) :: o
      o = created(self)
      if (o%status == CW_OK) o = status_outcome(self, capi_transient_rewind(handle_of(self)))
      if (present(errmsg)) call set_errmsg(o, errmsg)
      call deliver(o, stat)
   end subroutine transient_rewind

   ! The length of a saved state in 64-bit words (0 before create).
   integer function transient_state_size(self)
      class(cw_transient_type), intent(in) :: self
      integer(c_size_t) :: words
      integer(c_int) :: status
      words = 0
      transient_state_size = 0
      if (.not. self%is_created()) return
      status = capi_transient_state_size(handle_of(self), words)
      if (status == CW_OK) transient_state_size = int(words)
   end function transient_state_size

   ! The committed state into state(1:state_size()) (the words are
   ! uint64_t in C, seen here as integer(c_int64_t): keep them as they are).
   subroutine transient_save(self, state, stat, errmsg)
      class(cw_transient_type), intent(in) :: self
      integer(c_int64_t), intent(inout), contiguous :: state(:)
      integer, intent(out), optional :: stat
      character(len=:), allocatable, intent(out), optional :: errmsg
      type(outcome) :: o
      o = created(self)
      if (o%status == CW_OK) o = status_outcome(self, capi_transient_save( &
                                 handle_of(self), state, size(state, kind=c_size_t)))
      if (present(errmsg)) call set_errmsg(o, errmsg)
      call deliver(o, stat)
   end subroutine transient_save

   ! Makes a saved state (save's words, all of them) the committed state
   ! and drops any trial.
   subroutine transient_restore(self, state, stat, errmsg)
      class(cw_transient_type), intent(inout) :: self
      integer(c_int64_t), intent(in), contiguous :: state(:)
      integer, intent(out), optional :: stat
      character(len=:), allocatable, intent(out), optional :: errmsg
      type(outcome) :: o
      o = created(self)
      if (o%status == CW_OK) o = status_outcome(self, capi_transient_restore( &
                                 handle_of(self), state, size(state, kind=c_size_t)))
      if (present(errmsg)) call set_errmsg(o, errmsg)
      call deliver(o, stat)
   end subroutine transient_restore

   ! A field of the last step (CW_FIELD_X, _Y, _PZ, _PX, _PY, _SX, _SY,
   ! _WORK_CONSISTENT; sx, sy the slip of the step [m], the work [J]) into
   ! out(nx, ny).
   subroutine transient_get_field_2d(self, field, out, stat, errmsg)
      class(cw_transient_type), intent(in) :: self
      integer, intent(in) :: field
      real(c_double), intent(inout), contiguous :: out(:, :)
      integer, intent(out), optional :: stat
      character(len=:), allocatable, intent(out), optional :: errmsg
      type(outcome) :: o
      o = created_map(self, shape(out))
      if (o%status == CW_OK) o = status_outcome(self, capi_transient_get_field( &
                                 handle_of(self), int(field, c_int), out, size(out, kind=c_size_t)))
      if (present(errmsg)) call set_errmsg(o, errmsg)
      call deliver(o, stat)
   end subroutine transient_get_field_2d

   subroutine transient_get_field_1d(self, field, out, stat, errmsg)
      class(cw_transient_type), intent(in) :: self
      integer, intent(in) :: field
      real(c_double), intent(inout), contiguous :: out(:)
      integer, intent(out), optional :: stat
      character(len=:), allocatable, intent(out), optional :: errmsg
      type(outcome) :: o
      o = created(self)
      if (o%status == CW_OK) o = status_outcome(self, capi_transient_get_field( &
                                 handle_of(self), int(field, c_int), out, size(out, kind=c_size_t)))
      if (present(errmsg)) call set_errmsg(o, errmsg)
      call deliver(o, stat)
   end subroutine transient_get_field_1d

   ! The element states of the last step (CW_STATE_*) into out(nx, ny).
   subroutine transient_get_state_2d(self, out, stat, errmsg)
      class(cw_transient_type), intent(in) :: self
      integer(c_int), intent(inout), contiguous :: out(:, :)
      integer, intent(out), optional :: stat
      character(len=:), allocatable, intent(out), optional :: errmsg
      type(outcome) :: o
      o = created_map(self, shape(out))
      if (o%status == CW_OK) o = status_outcome(self, capi_transient_get_state( &
                                 handle_of(self), out, size(out, kind=c_size_t)))
      if (present(errmsg)) call set_errmsg(o, errmsg)
      call deliver(o, stat)
   end subroutine transient_get_state_2d

   subroutine transient_get_state_1d(self, out, stat, errmsg)
      class(cw_transient_type), intent(in) :: self
      integer(c_int), intent(inout), contiguous :: out(:)
      integer, intent(out), optional :: stat
      character(len=:), allocatable, intent(out), optional :: errmsg
      type(outcome) :: o
      o = created(self)
      if (o%status == CW_OK) o = status_outcome(self, capi_transient_get_state( &
                                 handle_of(self), out, size(out, kind=c_size_t)))
      if (present(errmsg)) call set_errmsg(o, errmsg)
      call deliver(o, stat)
   end subroutine transient_get_state_1d

   ! CW_COORDINATES_CONTACT (the default) or CW_COORDINATES_WORLD (the exact
   ! model's: the geometry moves over the grid); starts from zero tractions.
   subroutine transient_set_coordinates(self, coordinates, stat, errmsg)
      class(cw_transient_type), intent(inout) :: self
      integer, intent(in) :: coordinates
      integer, intent(out), optional :: stat
      character(len=:), allocatable, intent(out), optional :: errmsg
      type(outcome) :: o
      o = created(self)
      if (o%status == CW_OK) o = status_outcome(self, capi_transient_set_coordinates( &
                                 handle_of(self), int(coordinates, c_int)))
      if (present(errmsg)) call set_errmsg(o, errmsg)
      call deliver(o, stat)
   end subroutine transient_set_coordinates

   ! The last step's derivative (the exact model's): jacobian(r, c) =
   ! d(output r)/d(input c), rows Fx, Fy, Mz and columns xi_x, xi_y, phi with
   ! creepages given (the C API's jacobian[3*(r-1) + c-1]; a prescribed force
   ! and its found creepage trade places). Nothing is written on error.
   subroutine transient_jacobian(self, jacobian, stat, errmsg)
      class(cw_transient_type), intent(inout) :: self
      real(c_double), intent(inout) :: jacobian(3, 3)
      integer, intent(out), optional :: stat
      character(len=:), allocatable, intent(out), optional :: errmsg
      real(c_double) :: rows(CW_TRANSIENT_JACOBIAN_LEN)
      type(outcome) :: o
      o = created(self)
      if (o%status == CW_OK) then
         o = status_outcome(self, capi_transient_jacobian(handle_of(self), rows, &
                                                          size(rows, kind=c_size_t)))
         if (o%status == CW_OK) jacobian = transpose(reshape(rows, [3, 3]))
      end if
      if (present(errmsg)) call set_errmsg(o, errmsg)
      call deliver(o, stat)
   end subroutine transient_jacobian

   ! Adds the wear of the last step by params' law (default: the defaults
   ! of cw_wear_params_init); step_mass (optional) receives its mass [kg].
   ! Add each step once, after it is committed.
   subroutine transient_add_wear(self, params, step_mass, stat, errmsg)
      class(cw_transient_type), intent(inout) :: self
      type(cw_wear_params), intent(in), optional :: params
      real(c_double), intent(out), optional :: step_mass
      integer, intent(out), optional :: stat
      character(len=:), allocatable, intent(out), optional :: errmsg
      type(cw_wear_params) :: p
      real(c_double) :: m
      integer(c_int) :: status
      type(outcome) :: o
      o = created(self)
      if (o%status == CW_OK) then
         if (present(params)) then
            p = params
         else
            status = capi_wear_params_init(p)
         end if
         m = 0
         o = status_outcome(self, capi_transient_add_wear(handle_of(self), p, m))
         if (o%status == CW_OK .and. present(step_mass)) step_mass = m
      end if
      if (present(errmsg)) call set_errmsg(o, errmsg)
      call deliver(o, stat)
   end subroutine transient_add_wear

   ! The accumulated wear: the total [kg] into mass and (optional) the mass
   ! per element [kg] into mass_map(nx, ny).
   subroutine transient_get_wear(self, mass, mass_map, stat, errmsg)
      class(cw_transient_type), intent(in) :: self
      real(c_double), intent(out) :: mass
      real(c_double), intent(inout), contiguous, target, optional :: mass_map(:, :)
      integer, intent(out), optional :: stat
      character(len=:), allocatable, intent(out), optional :: errmsg
      type(c_ptr) :: map
      integer(c_size_t) :: len
      real(c_double) :: m
      type(outcome) :: o
      map = c_null_ptr
      len = 0
      m = 0
      if (present(mass_map)) then
         o = created_map(self, shape(mass_map))
         map = c_loc(mass_map)
         len = size(mass_map, kind=c_size_t)
      else
         o = created(self)
      end if
      if (o%status == CW_OK) o = status_outcome(self, capi_transient_get_wear( &
                                 handle_of(self), map, len, m))
      mass = m
      if (present(errmsg)) call set_errmsg(o, errmsg)
      call deliver(o, stat)
   end subroutine transient_get_wear

   ! Clears the accumulated wear.
   subroutine transient_reset_wear(self, stat, errmsg)
      class(cw_transient_type), intent(inout) :: self
      integer, intent(out), optional :: stat
      character(len=:), allocatable, intent(out), optional :: errmsg
      type(outcome) :: o
      o = created(self)
      if (o%status == CW_OK) o = status_outcome(self, capi_transient_reset_wear(handle_of(self)))
      if (present(errmsg)) call set_errmsg(o, errmsg)
      call deliver(o, stat)
   end subroutine transient_reset_wear

end module creepwork_transient
