! Wheel/rail contact (header section "wheel/rail", doc/wheelrail.md):
!   cw_wheelrail_type  owns one cw_wheelrail: a wheel and a rail profile, the
!                      track, the wheelset and the side; solved for any
!                      wheelset position, every contact patch by Kalker's
!                      exact theory or the fast model; each patch's fields,
!                      and its wear on the rail and wheel profiles. CONTACT's
!                      module-1 conventions (forces on the rail), SI units.
module creepwork_wheelrail
   use, intrinsic :: iso_c_binding, only: c_int, c_size_t, c_double, c_char, c_ptr, c_null_char, &
                                          c_null_ptr, c_loc
   use creepwork_types
   use creepwork_capi
   use creepwork_handle
   use creepwork_wear, only: cw_wear_profile_type
   use creepwork_checks, only: allocate_checks
   implicit none
   private
   public :: cw_wheelrail_params_init, cw_wheelrail_motion_init, cw_wheelrail_totals_init, &
             cw_wheelrail_patch_init

   type, public, extends(cw_handle) :: cw_wheelrail_type
   contains
      procedure :: create => wheelrail_create
      procedure :: create_points => wheelrail_create_points
      procedure :: solve => wheelrail_solve
      procedure :: get_patch => wheelrail_get_patch
      procedure :: get_patch_field => wheelrail_get_patch_field
      procedure :: get_patch_state => wheelrail_get_patch_state
      procedure :: add_wear => wheelrail_add_wear
      procedure :: get_profile => wheelrail_get_profile
      procedure :: check => wheelrail_check
      procedure, nopass :: noun => wheelrail_noun
   end type cw_wheelrail_type

contains

   ! The C _init functions fail only on a NULL pointer, which a Fortran
   ! argument cannot be.
   subroutine cw_wheelrail_params_init(params)
      type(cw_wheelrail_params), intent(out) :: params
      integer(c_int) :: status
      status = capi_wheelrail_params_init(params)
   end subroutine cw_wheelrail_params_init

   subroutine cw_wheelrail_motion_init(motion)
      type(cw_wheelrail_motion), intent(out) :: motion
      integer(c_int) :: status
      status = capi_wheelrail_motion_init(motion)
   end subroutine cw_wheelrail_motion_init

   subroutine cw_wheelrail_totals_init(totals)
      type(cw_wheelrail_totals), intent(out) :: totals
      integer(c_int) :: status
      status = capi_wheelrail_totals_init(totals)
   end subroutine cw_wheelrail_totals_init

   subroutine cw_wheelrail_patch_init(patch)
      type(cw_wheelrail_patch), intent(out) :: patch
      integer(c_int) :: status
      status = capi_wheelrail_patch_init(patch)
   end subroutine cw_wheelrail_patch_init

   function wheelrail_noun() result(s)
      character(len=noun_length) :: s
      s = 'wheel/rail'
   end function wheelrail_noun

   ! From profile files (SIMPACK .prr/.prw, MiniProf .ban/.whl, or a table);
   ! params default to cw_wheelrail_params_init's (destroys a previous one).
   subroutine wheelrail_create(self, rail_file, wheel_file, params, stat, errmsg)
      class(cw_wheelrail_type), intent(inout) :: self
      character(len=*), intent(in) :: rail_file, wheel_file
      type(cw_wheelrail_params), intent(in), optional :: params
      integer, intent(out), optional :: stat
      character(len=:), allocatable, intent(out), optional :: errmsg
      character(kind=c_char) :: buffer(message_capacity)
      type(cw_wheelrail_params) :: p
      type(c_ptr) :: handle
      type(outcome) :: o
      call self%destroy()
      call params_or_default(params, p)
      buffer(1) = c_null_char
      o = buffer_outcome(capi_wheelrail_create(p, c_chars(rail_file), c_chars(wheel_file), handle, &
                                               buffer, size(buffer, kind=c_size_t)), buffer)
      if (o%status == CW_OK) call adopt(self, handle, capi_wheelrail_destroy, &
                                        capi_wheelrail_last_error, 1, 1)
      if (present(errmsg)) call set_errmsg(o, errmsg)
      call deliver(o, stat)
   end subroutine wheelrail_create

   ! From points (y towards the field side, z down) in units of
   ! params%profile_unit (0: metres).
   subroutine wheelrail_create_points(self, rail_y, rail_z, wheel_y, wheel_z, params, stat, errmsg)
      class(cw_wheelrail_type), intent(inout) :: self
      real(c_double), intent(in), contiguous :: rail_y(:), rail_z(:), wheel_y(:), wheel_z(:)
      type(cw_wheelrail_params), intent(in), optional :: params
      integer, intent(out), optional :: stat
      character(len=:), allocatable, intent(out), optional :: errmsg
      character(kind=c_char) :: buffer(message_capacity)
      type(cw_wheelrail_params) :: p
      type(c_ptr) :: handle
      type(outcome) :: o
      call self%destroy()
      call params_or_default(params, p)
      buffer(1) = c_null_char
      if (size(rail_z) /= size(rail_y) .or. size(wheel_z) /= size(wheel_y)) then
         o = make_outcome(CW_ERR_INVALID_INPUT, 'rail_y and rail_z (wheel_y and wheel_z) must have '// &
                          'the same size')
      else
         o = buffer_outcome(capi_wheelrail_create_points(p, rail_y, rail_z, size(rail_y, kind=c_size_t), &
                                                         wheel_y, wheel_z, size(wheel_y, kind=c_size_t), &
                                                         handle, buffer, size(buffer, kind=c_size_t)), buffer)
      end if
      if (o%status == CW_OK) call adopt(self, handle, capi_wheelrail_destroy, &
                                        capi_wheelrail_last_error, 1, 1)
      if (present(errmsg)) call set_errmsg(o, errmsg)
      call deliver(o, stat)
   end subroutine wheelrail_create_points

   ! One wheelset position: with Fz [N] present the height is found for that
   ! vertical force (starting from motion%z), otherwise motion%z is the
   ! height. An uninitialised totals (struct_size 0) is initialised first.
   subroutine wheelrail_solve(self, motion, totals, Fz, stat, errmsg)
      class(cw_wheelrail_type), intent(inout) :: self
      type(cw_wheelrail_motion), intent(in) :: motion
      type(cw_wheelrail_totals), intent(inout) :: totals
      real(c_double), intent(in), optional :: Fz
      integer, intent(out), optional :: stat
      character(len=:), allocatable, intent(out), optional :: errmsg
      integer(c_int) :: load, status
      real(c_double) :: force
      type(outcome) :: o
      o = created(self)
      if (o%status == CW_OK) then
         load = CW_WHEELRAIL_HEIGHT
         force = 0
         if (present(Fz)) then
            load = CW_WHEELRAIL_FORCE
            force = Fz
         end if
         if (totals%struct_size == 0) status = capi_wheelrail_totals_init(totals)
         o = status_outcome(self, capi_wheelrail_solve(handle_of(self), motion, load, force, totals))
      end if
      if (present(errmsg)) call set_errmsg(o, errmsg)
      call deliver(o, stat)
   end subroutine wheelrail_solve

   ! Patch k (1-based, k <= totals%n_patches) of the last solve.
   subroutine wheelrail_get_patch(self, k, patch, stat, errmsg)
      class(cw_wheelrail_type), intent(in) :: self
      integer, intent(in) :: k
      type(cw_wheelrail_patch), intent(inout) :: patch
      integer, intent(out), optional :: stat
      character(len=:), allocatable, intent(out), optional :: errmsg
      integer(c_int) :: status
      type(outcome) :: o
      o = patch_index_checked(self, k)
      if (o%status == CW_OK) then
         if (patch%struct_size == 0) status = capi_wheelrail_patch_init(patch)
         o = status_outcome(self, capi_wheelrail_get_patch(handle_of(self), int(k - 1, c_size_t), patch))
      end if
      if (present(errmsg)) call set_errmsg(o, errmsg)
      call deliver(o, stat)
   end subroutine wheelrail_get_patch

   ! Field CW_FIELD_* of patch k (1-based) into out(field_nx*field_ny or
   ! longer), element (i, j) of the patch's field grid at i + (j-1)*field_nx.
   subroutine wheelrail_get_patch_field(self, k, field, out, stat, errmsg)
      class(cw_wheelrail_type), intent(in) :: self
      integer, intent(in) :: k, field
      real(c_double), intent(inout), contiguous :: out(:)
      integer, intent(out), optional :: stat
      character(len=:), allocatable, intent(out), optional :: errmsg
      type(outcome) :: o
      o = patch_index_checked(self, k)
      if (o%status == CW_OK) o = status_outcome(self, capi_wheelrail_get_patch_field( &
                                 handle_of(self), int(k - 1, c_size_t), int(field, c_int), out, &
                                 size(out, kind=c_size_t)))
      if (present(errmsg)) call set_errmsg(o, errmsg)
      call deliver(o, stat)
   end subroutine wheelrail_get_patch_field

   ! CW_STATE_* per element of patch k, as get_patch_field.
   subroutine wheelrail_get_patch_state(self, k, out, stat, errmsg)
      class(cw_wheelrail_type), intent(in) :: self
      integer, intent(in) :: k
      integer(c_int), intent(inout), contiguous :: out(:)
      integer, intent(out), optional :: stat
      character(len=:), allocatable, intent(out), optional :: errmsg
      type(outcome) :: o
      o = patch_index_checked(self, k)
      if (o%status == CW_OK) o = status_outcome(self, capi_wheelrail_get_patch_state( &
                                 handle_of(self), int(k - 1, c_size_t), out, size(out, kind=c_size_t)))
      if (present(errmsg)) call set_errmsg(o, errmsg)
      call deliver(o, stat)
   end subroutine wheelrail_get_patch_state

   ! The wear of every patch of the last solve by the law in params, passes
   ! times, on the rail's and the wheel's profile grids (each optional);
   ! result sums the patches' wear per pass.
   subroutine wheelrail_add_wear(self, params, passes, rail, wheel, result, stat, errmsg)
      class(cw_wheelrail_type), intent(in) :: self
      type(cw_wear_params), intent(in) :: params
      real(c_double), intent(in) :: passes
      class(cw_wear_profile_type), intent(in), optional :: rail, wheel
      type(cw_wear_result), intent(inout), target, optional :: result
      integer, intent(out), optional :: stat
      character(len=:), allocatable, intent(out), optional :: errmsg
      type(c_ptr) :: pr, pw, pres
      integer(c_int) :: status
      type(outcome) :: o
      o = created(self)
      pr = c_null_ptr
      pw = c_null_ptr
      pres = c_null_ptr
      if (present(rail) .and. o%status == CW_OK) then
         o = created(rail)
         pr = handle_of(rail)
      end if
      if (present(wheel) .and. o%status == CW_OK) then
         o = created(wheel)
         pw = handle_of(wheel)
      end if
      if (present(result)) then
         if (result%struct_size == 0) status = capi_wear_result_init(result)
         pres = c_loc(result)
      end if
      if (o%status == CW_OK) o = status_outcome(self, capi_wheelrail_add_wear( &
                                 handle_of(self), params, passes, pr, pw, pres))
      if (present(errmsg)) call set_errmsg(o, errmsg)
      call deliver(o, stat)
   end subroutine wheelrail_add_wear

   ! The rail's (which = CW_WHEELRAIL_RAIL) or the wheel's profile points in
   ! track coordinates at the last solve's position, into y and z
   ! (allocated here to the number of points).
   subroutine wheelrail_get_profile(self, which, y, z, stat, errmsg)
      class(cw_wheelrail_type), intent(in) :: self
      integer, intent(in) :: which
      real(c_double), allocatable, intent(out) :: y(:), z(:)
      integer, intent(out), optional :: stat
      character(len=:), allocatable, intent(out), optional :: errmsg
      integer(c_size_t) :: count
      integer(c_int) :: status
      real(c_double) :: none(1)
      type(outcome) :: o
      o = created(self)
      if (o%status == CW_OK) then
         count = 0
         status = capi_wheelrail_get_profile(handle_of(self), int(which, c_int), none, none, 0_c_size_t, count)
         if (status == CW_ERR_BUFFER_TOO_SMALL .or. status == CW_OK) then
            allocate (y(count), z(count))
            status = capi_wheelrail_get_profile(handle_of(self), int(which, c_int), y, z, count, count)
         end if
         o = status_outcome(self, status)
      end if
      if (present(errmsg)) call set_errmsg(o, errmsg)
      call deliver(o, stat)
   end subroutine wheelrail_get_profile

   ! created(self) and k >= 1.
   function patch_index_checked(self, k) result(o)
      class(cw_wheelrail_type), intent(in) :: self
      integer, intent(in) :: k
      type(outcome) :: o
      o = created(self)
      if (o%status == CW_OK .and. k < 1) &
         o = make_outcome(CW_ERR_INVALID_INPUT, 'k = '//trim(integer_text(k))//' must be >= 1')
   end function patch_index_checked

   subroutine params_or_default(params, p)
      type(cw_wheelrail_params), intent(in), optional :: params
      type(cw_wheelrail_params), intent(out) :: p
      integer(c_int) :: status
      if (present(params)) then
         p = params
      else
         status = capi_wheelrail_params_init(p)
      end if
   end subroutine params_or_default

   ! A NUL-terminated copy of text for the C side.
   ! The case's inputs and the last solve checked (cw_wheelrail_check):
   ! checks receives one entry per finding (size 0: none) -- inputs in a
   ! wrong unit, a patch on the wheel's flange tip, a wheelset height beyond
   ! 5 mm on a tread contact, a wheel profile whose origin is off -- each
   ! with its likely cause; cw_check_text(checks(k)%message) to print.
   subroutine wheelrail_check(self, checks, stat, errmsg)
      class(cw_wheelrail_type), intent(in) :: self
      type(cw_check), allocatable, intent(out) :: checks(:)
      integer, intent(out), optional :: stat
      character(len=:), allocatable, intent(out), optional :: errmsg
      type(cw_check) :: none(1)
      integer(c_size_t) :: found
      type(outcome) :: o
      o = created(self)
      if (o%status == CW_OK) then
         found = 0
         o = status_outcome(self, capi_wheelrail_check(handle_of(self), none, 0_c_size_t, found))
      end if
      if (o%status == CW_OK) then
         call allocate_checks(checks, found)
         if (found > 0) o = status_outcome(self, capi_wheelrail_check(handle_of(self), checks, found, found))
      end if
      if (.not. allocated(checks)) allocate (checks(0))
      if (present(errmsg)) call set_errmsg(o, errmsg)
      call deliver(o, stat)
   end subroutine wheelrail_check

end module creepwork_wheelrail
