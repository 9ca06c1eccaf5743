! cw_batch_type: owns one cw_batch -- many independent contacts on one grid,
! in parallel (OpenMP), bitwise equal to one-by-one solves.
module creepwork_batch
   use, intrinsic :: iso_c_binding, only: c_int, c_size_t, c_double, c_char, c_ptr, c_null_ptr, &
                                          c_null_char, c_loc
   use creepwork_types
   use creepwork_capi
   use creepwork_handle
   implicit none
   private

   type, public, extends(cw_handle) :: cw_batch_type
   contains
      procedure :: create => batch_create
      procedure :: prepare => batch_prepare
      procedure :: solve => batch_solve
      procedure, nopass :: noun => batch_noun
   end type cw_batch_type

contains

   function batch_noun() result(s)
      character(len=noun_length) :: s
      s = 'batch'
   end function batch_noun

   ! Creates a batch (destroying a previous one) on a grid as in
   ! cw_solver_type%create; threads <= 0 (default): all available cores.
   subroutine batch_create(self, grid, nx, ny, kind, box_scale, threads, stat, errmsg)
      class(cw_batch_type), intent(inout) :: self
      type(cw_grid), intent(in), optional :: grid
      integer, intent(in), optional :: nx, ny, kind
      real(c_double), intent(in), optional :: box_scale
      integer, intent(in), optional :: threads
      integer, intent(out), optional :: stat
      character(len=:), allocatable, intent(out), optional :: errmsg
      character(kind=c_char) :: buffer(message_capacity)
      type(c_ptr) :: handle
      type(outcome) :: o
      call self%destroy()
      buffer(1) = c_null_char
      o = buffer_outcome(capi_batch_create(make_grid(grid, nx, ny, kind, box_scale), &
                                         int_or(threads, 0_c_int), handle, buffer, &
                                         size(buffer, kind=c_size_t)), buffer)
      if (o%status == CW_OK) call adopt(self, handle, capi_batch_destroy, capi_batch_last_error, 0, 0)
      if (present(errmsg)) call set_errmsg(o, errmsg)
      call deliver(o, stat)
   end subroutine batch_create

   ! cw_solver_type%prepare for the solver of every thread of the batch
   ! (cw_batch_prepare).
   subroutine batch_prepare(self, model, stat, errmsg)
      class(cw_batch_type), intent(inout) :: self
      integer, intent(in) :: model
      integer, intent(out), optional :: stat
      character(len=:), allocatable, intent(out), optional :: errmsg
      type(outcome) :: o
      o = created(self)
      if (o%status == CW_OK) o = status_outcome(self, capi_batch_prepare(handle_of(self), &
                                                                         int(model, c_int)))
      if (present(errmsg)) call set_errmsg(o, errmsg)
      call deliver(o, stat)
   end subroutine batch_prepare

   ! Solves size(params) independent contacts into results(1:size(params))
   ! (results bitwise equal to one-by-one solves). statuses (optional)
   ! receives each contact's status. Uninitialised results are initialised.
   subroutine batch_solve(self, params, mode, results, statuses, stat, errmsg)
      class(cw_batch_type), intent(inout) :: self
      type(cw_params), intent(in), contiguous :: params(:)
      integer, intent(in) :: mode
      type(cw_result), intent(inout), contiguous :: results(:)
      integer(c_int), intent(inout), contiguous, target, optional :: statuses(:)
      integer, intent(out), optional :: stat
      character(len=:), allocatable, intent(out), optional :: errmsg
      type(c_ptr) :: ps
      type(outcome) :: o
      integer :: i
      integer(c_int) :: status
      o = created(self)
      if (o%status /= CW_OK) then
         continue
      else if (size(results) < size(params)) then
         o = too_short('results', size(results), size(params))
      else if (present(statuses)) then
         if (size(statuses) < size(params)) o = too_short('statuses', size(statuses), size(params))
      end if
      if (o%status == CW_OK) then
         ps = c_null_ptr
         if (present(statuses)) ps = c_loc(statuses)
         do i = 1, size(params)
            if (results(i)%struct_size == 0) status = capi_result_init(results(i))
         end do
         o = status_outcome(self, capi_batch_solve(handle_of(self), size(params, kind=c_size_t), &
                                                   params, int(mode, c_int), results, ps))
      end if
      if (present(errmsg)) call set_errmsg(o, errmsg)
      call deliver(o, stat)
   end subroutine batch_solve

   ! Buffer of n elements where count are needed.
   function too_short(name, n, count) result(o)
      character(len=*), intent(in) :: name
      integer, intent(in) :: n, count
      type(outcome) :: o
      o = make_outcome(CW_ERR_BUFFER_TOO_SMALL, name//' holds '//trim(integer_text(n))//' but '// &
                       trim(integer_text(count))//' are needed')
   end function too_short

end module creepwork_batch
