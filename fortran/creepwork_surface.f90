! Surface temperature and damage indices of a solved contact (header
! sections "temperature" and "damage", doc/theory/temperature.md and
! doc/theory/damage.md). Body 1 is the rail, body 2 the wheel.
!   cw_temperature_type  owns one cw_temperature: both bodies' steady
!                        surface temperatures, for one solver grid
!   cw_damage_type       owns one cw_damage: the RCF index and T_gamma
!                        density per element, FI_surf, T_gamma and the WLRM
!                        damage per pass
! The _init procedures of their structs are here (the C ones fail only on a
! NULL pointer, which a Fortran argument cannot be).
module creepwork_surface
   use, intrinsic :: iso_c_binding, only: c_int, c_size_t, c_double, c_ptr, c_null_ptr, c_loc
   use creepwork_types
   use creepwork_capi
   use creepwork_handle
   use creepwork_solver, only: cw_solver_type
   implicit none
   private
   public :: cw_temperature_params_init, cw_temperature_result_init
   public :: cw_damage_params_init, cw_damage_result_init

   type, public, extends(cw_handle) :: cw_temperature_type
   contains
      procedure :: create => temperature_create
      procedure :: compute => temperature_compute
      procedure, private :: temperature_get_field_2d, temperature_get_field_1d
      generic :: get_field => temperature_get_field_2d, temperature_get_field_1d
      procedure :: get_result => temperature_get_result
      procedure, nopass :: noun => temperature_noun
   end type cw_temperature_type

   type, public, extends(cw_handle) :: cw_damage_type
   contains
      procedure :: create => damage_create
      procedure :: compute => damage_compute
      procedure, private :: damage_get_field_2d, damage_get_field_1d
      generic :: get_field => damage_get_field_2d, damage_get_field_1d
      procedure :: get_result => damage_get_result
      procedure, nopass :: noun => damage_noun
   end type cw_damage_type

contains

   ! ================================================================ temperature

   subroutine cw_temperature_params_init(params)
      type(cw_temperature_params), intent(out) :: params
      integer(c_int) :: status
      status = capi_temperature_params_init(params)
   end subroutine cw_temperature_params_init

   subroutine cw_temperature_result_init(result)
      type(cw_temperature_result), intent(out) :: result
      integer(c_int) :: status
      status = capi_temperature_result_init(result)
   end subroutine cw_temperature_result_init

   function temperature_noun() result(s)
      character(len=noun_length) :: s
      s = 'temperature'
   end function temperature_noun

   ! Creates the temperature workspace for the grid of solver (destroying a
   ! previous one).
   subroutine temperature_create(self, solver, stat, errmsg)
      class(cw_temperature_type), intent(inout) :: self
      class(cw_solver_type), intent(in) :: solver
      integer, intent(out), optional :: stat
      character(len=:), allocatable, intent(out), optional :: errmsg
      type(c_ptr) :: handle
      integer :: nx, ny
      type(outcome) :: o
      call self%destroy()
      o = created(solver)
      if (o%status == CW_OK) o = make_outcome(capi_temperature_create(handle_of(solver), handle), '')
      if (o%status == CW_OK) then
         call grid_of(solver, nx, ny)
         call adopt(self, handle, capi_temperature_destroy, capi_temperature_last_error, nx, ny)
      end if
      if (present(errmsg)) call set_errmsg(o, errmsg)
      call deliver(o, stat)
   end subroutine temperature_create

   ! The temperature of solver's last CW_SOLVE_FULL solve from params (as set up by
   ! cw_temperature_params_init); result is optional, an uninitialised one
   ! (struct_size 0) is initialised first.
   subroutine temperature_compute(self, solver, params, result, stat, errmsg)
      class(cw_temperature_type), intent(inout) :: self
      class(cw_solver_type), intent(in) :: solver
      type(cw_temperature_params), intent(in) :: params
      type(cw_temperature_result), intent(inout), target, optional :: result
      integer, intent(out), optional :: stat
      character(len=:), allocatable, intent(out), optional :: errmsg
      type(c_ptr) :: pr
      integer(c_int) :: status
      type(outcome) :: o
      o = created(self)
      if (o%status == CW_OK) o = created(solver)
      if (o%status == CW_OK) then
         pr = c_null_ptr
         if (present(result)) then
            if (result%struct_size == 0) status = capi_temperature_result_init(result)
            pr = c_loc(result)
         end if
         o = status_outcome(self, capi_temperature_compute(handle_of(self), handle_of(solver), params, pr))
      end if
      if (present(errmsg)) call set_errmsg(o, errmsg)
      call deliver(o, stat)
   end subroutine temperature_compute

   ! A CW_TEMPERATURE_FIELD_* of the last compute into out(nx, ny).
   subroutine temperature_get_field_2d(self, field, out, stat, errmsg)
      class(cw_temperature_type), intent(in) :: self
      integer, intent(in) :: field
      real(c_double), intent(inout), contiguous :: out(:, :)
      integer, intent(out), optional :: stat
      character(len=:), allocatable, intent(out), optional :: errmsg
      type(outcome) :: o
      o = created_map(self, shape(out))
      if (o%status == CW_OK) o = status_outcome(self, capi_temperature_get_field( &
                                 handle_of(self), int(field, c_int), out, size(out, kind=c_size_t)))
      if (present(errmsg)) call set_errmsg(o, errmsg)
      call deliver(o, stat)
   end subroutine temperature_get_field_2d

   subroutine temperature_get_field_1d(self, field, out, stat, errmsg)
      class(cw_temperature_type), intent(in) :: self
      integer, intent(in) :: field
      real(c_double), intent(inout), contiguous :: out(:)
      integer, intent(out), optional :: stat
      character(len=:), allocatable, intent(out), optional :: errmsg
      type(outcome) :: o
      o = created(self)
      if (o%status == CW_OK) o = status_outcome(self, capi_temperature_get_field( &
                                 handle_of(self), int(field, c_int), out, size(out, kind=c_size_t)))
      if (present(errmsg)) call set_errmsg(o, errmsg)
      call deliver(o, stat)
   end subroutine temperature_get_field_1d

   ! The result of the last compute.
   subroutine temperature_get_result(self, result, stat, errmsg)
      class(cw_temperature_type), intent(in) :: self
      type(cw_temperature_result), intent(inout) :: result
      integer, intent(out), optional :: stat
      character(len=:), allocatable, intent(out), optional :: errmsg
      type(outcome) :: o
      integer(c_int) :: status
      o = created(self)
      if (o%status == CW_OK) then
         if (result%struct_size == 0) status = capi_temperature_result_init(result)
         o = status_outcome(self, capi_temperature_get_result(handle_of(self), result))
      end if
      if (present(errmsg)) call set_errmsg(o, errmsg)
      call deliver(o, stat)
   end subroutine temperature_get_result

   ! ================================================================ damage

   subroutine cw_damage_params_init(params)
      type(cw_damage_params), intent(out) :: params
      integer(c_int) :: status
      status = capi_damage_params_init(params)
   end subroutine cw_damage_params_init

   subroutine cw_damage_result_init(result)
      type(cw_damage_result), intent(out) :: result
      integer(c_int) :: status
      status = capi_damage_result_init(result)
   end subroutine cw_damage_result_init

   function damage_noun() result(s)
      character(len=noun_length) :: s
      s = 'damage'
   end function damage_noun

   ! Creates the damage workspace for the grid of solver (destroying a
   ! previous one).
   subroutine damage_create(self, solver, stat, errmsg)
      class(cw_damage_type), intent(inout) :: self
      class(cw_solver_type), intent(in) :: solver
      integer, intent(out), optional :: stat
      character(len=:), allocatable, intent(out), optional :: errmsg
      type(c_ptr) :: handle
      integer :: nx, ny
      type(outcome) :: o
      call self%destroy()
      o = created(solver)
      if (o%status == CW_OK) o = make_outcome(capi_damage_create(handle_of(solver), handle), '')
      if (o%status == CW_OK) then
         call grid_of(solver, nx, ny)
         call adopt(self, handle, capi_damage_destroy, capi_damage_last_error, nx, ny)
      end if
      if (present(errmsg)) call set_errmsg(o, errmsg)
      call deliver(o, stat)
   end subroutine damage_create

   ! The damage of solver's last CW_SOLVE_FULL solve from params (as set up by
   ! cw_damage_params_init); result is optional, an uninitialised one
   ! (struct_size 0) is initialised first.
   subroutine damage_compute(self, solver, params, result, stat, errmsg)
      class(cw_damage_type), intent(inout) :: self
      class(cw_solver_type), intent(in) :: solver
      type(cw_damage_params), intent(in) :: params
      type(cw_damage_result), intent(inout), target, optional :: result
      integer, intent(out), optional :: stat
      character(len=:), allocatable, intent(out), optional :: errmsg
      type(c_ptr) :: pr
      integer(c_int) :: status
      type(outcome) :: o
      o = created(self)
      if (o%status == CW_OK) o = created(solver)
      if (o%status == CW_OK) then
         pr = c_null_ptr
         if (present(result)) then
            if (result%struct_size == 0) status = capi_damage_result_init(result)
            pr = c_loc(result)
         end if
         o = status_outcome(self, capi_damage_compute(handle_of(self), handle_of(solver), params, pr))
      end if
      if (present(errmsg)) call set_errmsg(o, errmsg)
      call deliver(o, stat)
   end subroutine damage_compute

   ! A CW_DAMAGE_FIELD_* of the last compute into out(nx, ny).
   subroutine damage_get_field_2d(self, field, out, stat, errmsg)
      class(cw_damage_type), intent(in) :: self
      integer, intent(in) :: field
      real(c_double), intent(inout), contiguous :: out(:, :)
      integer, intent(out), optional :: stat
      character(len=:), allocatable, intent(out), optional :: errmsg
      type(outcome) :: o
      o = created_map(self, shape(out))
      if (o%status == CW_OK) o = status_outcome(self, capi_damage_get_field( &
                                 handle_of(self), int(field, c_int), out, size(out, kind=c_size_t)))
      if (present(errmsg)) call set_errmsg(o, errmsg)
      call deliver(o, stat)
   end subroutine damage_get_field_2d

   subroutine damage_get_field_1d(self, field, out, stat, errmsg)
      class(cw_damage_type), intent(in) :: self
      integer, intent(in) :: field
      real(c_double), intent(inout), contiguous :: out(:)
      integer, intent(out), optional :: stat
      character(len=:), allocatable, intent(out), optional :: errmsg
      type(outcome) :: o
      o = created(self)
      if (o%status == CW_OK) o = status_outcome(self, capi_damage_get_field( &
                                 handle_of(self), int(field, c_int), out, size(out, kind=c_size_t)))
      if (present(errmsg)) call set_errmsg(o, errmsg)
      call deliver(o, stat)
   end subroutine damage_get_field_1d

   ! The result of the last compute.
   subroutine damage_get_result(self, result, stat, errmsg)
      class(cw_damage_type), intent(in) :: self
      type(cw_damage_result), intent(inout) :: result
      integer, intent(out), optional :: stat
      character(len=:), allocatable, intent(out), optional :: errmsg
      type(outcome) :: o
      integer(c_int) :: status
      o = created(self)
      if (o%status == CW_OK) then
         if (result%struct_size == 0) status = capi_damage_result_init(result)
         o = status_outcome(self, capi_damage_get_result(handle_of(self), result))
      end if
      if (present(errmsg)) call set_errmsg(o, errmsg)
      call deliver(o, stat)
   end subroutine damage_get_result

end module creepwork_surface
