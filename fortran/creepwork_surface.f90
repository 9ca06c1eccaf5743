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
      procedure :: solve => temperature_solve
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

   ! Solves params with friction mu(T), mu piecewise linear through the points
   ! (temperatures(k), mu(k)), in cw_temperature_solve's fixed-point loop of
   ! solve and temperature (doc/theory/temperature.md): solver keeps the last
   ! solve, self its temperatures, temperature_result%iterations the passes.
   ! tolerance (default 1e-6) and max_iterations (default 100) as
   ! cw_mu_temperature's; results are optional, uninitialised ones are
   ! initialised first. temperatures and mu of different lengths:
   ! CW_ERR_INVALID_INPUT naming mu_T.
   subroutine temperature_solve(self, solver, params, temperature_params, temperatures, mu, &
                                result, temperature_result, tolerance, max_iterations, stat, errmsg)
      class(cw_temperature_type), intent(inout) :: self
      class(cw_solver_type), intent(inout) :: solver
      type(cw_params), intent(in) :: params
      type(cw_temperature_params), intent(in) :: temperature_params
      real(c_double), intent(in), target, contiguous :: temperatures(:), mu(:)
      type(cw_result), intent(inout), target, optional :: result
      type(cw_temperature_result), intent(inout), target, optional :: temperature_result
      real(c_double), intent(in), optional :: tolerance
      integer, intent(in), optional :: max_iterations
      integer, intent(out), optional :: stat
      character(len=:), allocatable, intent(out), optional :: errmsg
      type(c_ptr) :: pr, pt
      type(cw_mu_temperature) :: m
      integer(c_int) :: status
      type(outcome) :: o
      o = created(self)
      if (o%status == CW_OK) o = created(solver)
      if (o%status == CW_OK .and. size(temperatures) /= size(mu)) &
         o = make_outcome(CW_ERR_INVALID_INPUT, 'mu_T: temperatures and mu differ in length')
      if (o%status == CW_OK) then
         status = capi_mu_temperature_init(m)
         m%count = size(temperatures, kind=c_size_t)
         if (size(temperatures) > 0) then
            m%temperature = c_loc(temperatures)
            m%mu = c_loc(mu)
         end if
         if (present(tolerance)) m%tolerance = tolerance
         if (present(max_iterations)) m%max_iterations = int(max_iterations, c_int)
         pr = c_null_ptr
         pt = c_null_ptr
         if (present(result)) then
            if (result%struct_size == 0) status = capi_result_init(result)
            pr = c_loc(result)
         end if
         if (present(temperature_result)) then
            if (temperature_result%struct_size == 0) &
               status = capi_temperature_result_init(temperature_result)
            pt = c_loc(temperature_result)
         end if
         o = status_outcome(self, capi_temperature_solve(handle_of(self), handle_of(solver), &
                                  params, temperature_params, m, pr, pt))
      end if
      if (present(errmsg)) call set_errmsg(o, errmsg)
      call deliver(o, stat)
   end subroutine temperature_solve

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
