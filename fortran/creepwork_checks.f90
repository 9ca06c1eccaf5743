! The policy every door shares (header section "plausibility"): the
! plausibility checks of contacts (cw_params_check), of the surface
! post-processors' parameters (cw_temperature_params_check,
! cw_damage_params_check) and of a wheel/rail case
! (cw_wheelrail_type%check), the text of a finding, the default grid
! of a model and the canonical names of inputs and enumeration values.
module creepwork_checks
   use, intrinsic :: iso_c_binding, only: c_int, c_size_t, c_char, c_null_char
   use creepwork_types
   use creepwork_capi
   use creepwork_handle, only: outcome, make_outcome, set_errmsg, deliver, buffer_text, c_chars
   implicit none
   private
   public :: cw_check_init, cw_params_check, cw_check_text, cw_grid_init_model, cw_input_name
   public :: cw_temperature_params_check, cw_damage_params_check
   public :: allocate_checks

contains

   ! Zeroes and sets struct_size.
   subroutine cw_check_init(check)
      type(cw_check), intent(out) :: check
      integer(c_int) :: status
      status = capi_check_init(check)
   end subroutine cw_check_init

   ! checks := found initialised cw_check records (a count query's answer),
   ! ready for the check function to fill.
   subroutine allocate_checks(checks, found)
      type(cw_check), allocatable, intent(inout) :: checks(:)
      integer(c_size_t), intent(in) :: found
      integer :: k
      if (allocated(checks)) deallocate (checks)
      allocate (checks(found))
      do k = 1, int(found)
         call cw_check_init(checks(k))
      end do
   end subroutine allocate_checks

   ! The grid a model gets when none is given: for CW_MODEL_EXACT CONTACT's
   ! layout (uniform, 24 x 24 over 1.2 times the semi-axes), for the others
   ! cw_grid_init's. An unknown model is CW_ERR_UNKNOWN_OPTION.
   subroutine cw_grid_init_model(grid, model, stat, errmsg)
      type(cw_grid), intent(out) :: grid
      integer, intent(in) :: model
      integer, intent(out), optional :: stat
      character(len=:), allocatable, intent(out), optional :: errmsg
      type(outcome) :: o
      integer(c_int) :: status
      status = capi_grid_init_model(grid, int(model, c_int))
      if (status == CW_OK) then
         o = make_outcome(CW_OK, '')
      else
         o = make_outcome(status, 'model is not a CW_MODEL_*')
      end if
      if (present(errmsg)) call set_errmsg(o, errmsg)
      call deliver(o, stat)
   end subroutine cw_grid_init_model

   ! The contacts params(:) on grid checked for values that are valid but
   ! implausible for a wheel-rail contact (mm typed as m, kN as N, ...):
   ! checks receives one entry per rule broken (size 0: none), with the
   ! input, its value (the first contact's that breaks it), how many
   ! contacts break it and why; cw_check_text(checks(k)%message) is the
   ! message to print. The library never warns by itself.
   subroutine cw_params_check(grid, params, checks, stat, errmsg)
      type(cw_grid), intent(in) :: grid
      type(cw_params), intent(in) :: params(:)
      type(cw_check), allocatable, intent(out) :: checks(:)
      integer, intent(out), optional :: stat
      character(len=:), allocatable, intent(out), optional :: errmsg
      type(cw_check) :: none(1)
      integer(c_size_t) :: found
      integer(c_int) :: status
      type(outcome) :: o
      found = 0
      status = capi_params_check(grid, params, size(params, kind=c_size_t), none, 0_c_size_t, found)
      if (status == CW_OK) then
         call allocate_checks(checks, found)
         if (found > 0) status = capi_params_check(grid, params, size(params, kind=c_size_t), &
                                                   checks, found, found)
      end if
      if (.not. allocated(checks)) allocate (checks(0))
      if (status == CW_OK) then
         o = make_outcome(CW_OK, '')
      else
         o = make_outcome(status, 'cw_params_check: grid or params not initialised '// &
                          '(cw_grid_init, cw_params_init)')
      end if
      if (present(errmsg)) call set_errmsg(o, errmsg)
      call deliver(o, stat)
   end subroutine cw_params_check

   ! params checked for values that are valid but implausible for steel
   ! wheels and rails (conductivity in W/(mm K), heat capacity in kJ/(kg K),
   ! density in g/cm^3, rolling speed in km/h): checks receives one entry
   ! per finding (size 0: none); cw_check_text(checks(k)%message) to print.
   subroutine cw_temperature_params_check(params, checks, stat, errmsg)
      type(cw_temperature_params), intent(in) :: params
      type(cw_check), allocatable, intent(out) :: checks(:)
      integer, intent(out), optional :: stat
      character(len=:), allocatable, intent(out), optional :: errmsg
      type(cw_check) :: none(1)
      integer(c_size_t) :: found
      integer(c_int) :: status
      found = 0
      status = capi_temperature_params_check(params, none, 0_c_size_t, found)
      if (status == CW_OK) call allocate_checks(checks, found)
      if (status == CW_OK .and. found > 0) &
         status = capi_temperature_params_check(params, checks, found, found)
      call checks_outcome(status, 'cw_temperature_params_check', checks, stat, errmsg)
   end subroutine cw_temperature_params_check

   ! params checked as cw_temperature_params_check does: k_yield in MPa
   ! typed as Pa, WLRM thresholds in kN typed as N.
   subroutine cw_damage_params_check(params, checks, stat, errmsg)
      type(cw_damage_params), intent(in) :: params
      type(cw_check), allocatable, intent(out) :: checks(:)
      integer, intent(out), optional :: stat
      character(len=:), allocatable, intent(out), optional :: errmsg
      type(cw_check) :: none(1)
      integer(c_size_t) :: found
      integer(c_int) :: status
      found = 0
      status = capi_damage_params_check(params, none, 0_c_size_t, found)
      if (status == CW_OK) call allocate_checks(checks, found)
      if (status == CW_OK .and. found > 0) &
         status = capi_damage_params_check(params, checks, found, found)
      call checks_outcome(status, 'cw_damage_params_check', checks, stat, errmsg)
   end subroutine cw_damage_params_check

   ! The outcome of a parameter check: checks of size 0 after a failure
   ! (the params not initialised by their _init).
   subroutine checks_outcome(status, name, checks, stat, errmsg)
      integer(c_int), intent(in) :: status
      character(len=*), intent(in) :: name
      type(cw_check), allocatable, intent(inout) :: checks(:)
      integer, intent(out), optional :: stat
      character(len=:), allocatable, intent(out), optional :: errmsg
      type(outcome) :: o
      if (status /= CW_OK .and. allocated(checks)) deallocate (checks)
      if (.not. allocated(checks)) allocate (checks(0))
      if (status == CW_OK) then
         o = make_outcome(CW_OK, '')
      else
         o = make_outcome(status, name//': params not initialised (its _init)')
      end if
      if (present(errmsg)) call set_errmsg(o, errmsg)
      call deliver(o, stat)
   end subroutine checks_outcome

   ! The text of a character field of cw_check (input, unit, reason,
   ! message) up to its NUL.
   function cw_check_text(chars) result(s)
      character(kind=c_char), intent(in) :: chars(:)
      character(len=:), allocatable :: s
      call buffer_text(chars, s)
   end function cw_check_text

   ! The name every door documents for an input or enumeration value typed
   ! another way: 'N' -> 'normal_force', 'spin' -> 'phi', 'fast' ->
   ! 'fastsim', 'Semi-Hertz' -> 'semi_hertz'; any other name unchanged.
   function cw_input_name(typed) result(name)
      character(len=*), intent(in) :: typed
      character(len=:), allocatable :: name
      character(kind=c_char) :: buffer(len_trim(typed) + 32)
      buffer(1) = c_null_char
      if (capi_input_name(c_chars(typed), buffer, size(buffer, kind=c_size_t)) == CW_OK) then
         call buffer_text(buffer, name)
      else
         name = trim(typed)
      end if
   end function cw_input_name

end module creepwork_checks
