! cw_accumulator_type: owns one cw_accumulator -- the running work totals
! and maps of a simulation loop (paper eqs. 35, 37, 39).
module creepwork_accumulator
   use, intrinsic :: iso_c_binding, only: c_int, c_size_t, c_double, c_ptr
   use creepwork_types
   use creepwork_capi
   use creepwork_handle
   use creepwork_solver, only: cw_solver_type
   implicit none
   private

   type, public, extends(cw_handle) :: cw_accumulator_type
   contains
      procedure :: create => accumulator_create
      procedure :: reset => accumulator_reset
      procedure :: add => accumulator_add
      procedure :: get_totals => accumulator_get_totals
      procedure, private :: accumulator_get_field_2d, accumulator_get_field_1d
      generic :: get_field => accumulator_get_field_2d, accumulator_get_field_1d
      procedure :: get_strip_work => accumulator_get_strip_work
      procedure, nopass :: noun => accumulator_noun
   end type cw_accumulator_type

contains

   function accumulator_noun() result(s)
      character(len=noun_length) :: s
      s = 'accumulator'
   end function accumulator_noun

   ! Creates an accumulator on the grid of solver (destroying a previous one).
   subroutine accumulator_create(self, solver, stat, errmsg)
      class(cw_accumulator_type), intent(inout) :: self
      class(cw_solver_type), intent(in) :: solver
      integer, intent(out), optional :: stat
      character(len=:), allocatable, intent(out), optional :: errmsg
      type(c_ptr) :: handle
      integer :: nx, ny
      type(outcome) :: o
      call self%destroy()
      o = created(solver)
      if (o%status == CW_OK) o = make_outcome(capi_accumulator_create(handle_of(solver), handle), '')
      if (o%status == CW_OK) then
         call grid_of(solver, nx, ny)
         call adopt(self, handle, capi_accumulator_destroy, capi_accumulator_last_error, nx, ny)
      end if
      if (present(errmsg)) call set_errmsg(o, errmsg)
      call deliver(o, stat)
   end subroutine accumulator_create

   ! Back to zero totals.
   subroutine accumulator_reset(self, stat, errmsg)
      class(cw_accumulator_type), intent(inout) :: self
      integer, intent(out), optional :: stat
      character(len=:), allocatable, intent(out), optional :: errmsg
      type(outcome) :: o
      o = created(self)
      if (o%status == CW_OK) o = status_outcome(self, capi_accumulator_reset(handle_of(self)))
      if (present(errmsg)) call set_errmsg(o, errmsg)
      call deliver(o, stat)
   end subroutine accumulator_reset

   ! Adds the last CW_SOLVE_FULL solve of solver for a step of length
   ! distance = V*dt [m] (paper eqs. 35 and 37).
   subroutine accumulator_add(self, solver, distance, stat, errmsg)
      class(cw_accumulator_type), intent(inout) :: self
      class(cw_solver_type), intent(in) :: solver
      real(c_double), intent(in) :: distance
      integer, intent(out), optional :: stat
      character(len=:), allocatable, intent(out), optional :: errmsg
      type(outcome) :: o
      o = created(self)
      if (o%status == CW_OK) o = created(solver)
      if (o%status == CW_OK) o = status_outcome(self, capi_accumulator_add( &
                                 handle_of(self), handle_of(solver), distance))
      if (present(errmsg)) call set_errmsg(o, errmsg)
      call deliver(o, stat)
   end subroutine accumulator_add

   ! Running totals; an uninitialised totals (struct_size 0) is initialised first.
   subroutine accumulator_get_totals(self, totals, stat, errmsg)
      class(cw_accumulator_type), intent(in) :: self
      type(cw_accumulation), intent(inout) :: totals
      integer, intent(out), optional :: stat
      character(len=:), allocatable, intent(out), optional :: errmsg
      type(outcome) :: o
      integer(c_int) :: status
      o = created(self)
      if (o%status == CW_OK) then
         if (totals%struct_size == 0) status = capi_accumulation_init(totals)
         o = status_outcome(self, capi_accumulator_get_totals(handle_of(self), totals))
      end if
      if (present(errmsg)) call set_errmsg(o, errmsg)
      call deliver(o, stat)
   end subroutine accumulator_get_totals

   ! Accumulated work map [J] (CW_FIELD_WORK_PAPER or CW_FIELD_WORK_CONSISTENT)
   ! into out(nx, ny).
   subroutine accumulator_get_field_2d(self, field, out, stat, errmsg)
      class(cw_accumulator_type), intent(in) :: self
      integer, intent(in) :: field
      real(c_double), intent(inout), contiguous :: out(:, :)
      integer, intent(out), optional :: stat
      character(len=:), allocatable, intent(out), optional :: errmsg
      type(outcome) :: o
      o = created_map(self, shape(out))
      if (o%status == CW_OK) o = status_outcome(self, capi_accumulator_get_field( &
                                 handle_of(self), int(field, c_int), out, size(out, kind=c_size_t)))
      if (present(errmsg)) call set_errmsg(o, errmsg)
      call deliver(o, stat)
   end subroutine accumulator_get_field_2d

   subroutine accumulator_get_field_1d(self, field, out, stat, errmsg)
      class(cw_accumulator_type), intent(in) :: self
      integer, intent(in) :: field
      real(c_double), intent(inout), contiguous :: out(:)
      integer, intent(out), optional :: stat
      character(len=:), allocatable, intent(out), optional :: errmsg
      type(outcome) :: o
      o = created(self)
      if (o%status == CW_OK) o = status_outcome(self, capi_accumulator_get_field( &
                                 handle_of(self), int(field, c_int), out, size(out, kind=c_size_t)))
      if (present(errmsg)) call set_errmsg(o, errmsg)
      call deliver(o, stat)
   end subroutine accumulator_get_field_1d

   ! Accumulated energy-consistent work per strip j = 1..ny [J].
   subroutine accumulator_get_strip_work(self, out, stat, errmsg)
      class(cw_accumulator_type), intent(in) :: self
      real(c_double), intent(inout), contiguous :: out(:)
      integer, intent(out), optional :: stat
      character(len=:), allocatable, intent(out), optional :: errmsg
      type(outcome) :: o
      o = created(self)
      if (o%status == CW_OK) o = status_outcome(self, capi_accumulator_get_strip_work( &
                                 handle_of(self), out, size(out, kind=c_size_t)))
      if (present(errmsg)) call set_errmsg(o, errmsg)
      call deliver(o, stat)
   end subroutine accumulator_get_strip_work

end module creepwork_accumulator
