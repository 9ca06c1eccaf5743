! The Fortran layer of creepwork_bench: the benchmark loop of bench_main.cpp
! written against module creepwork (cw_solver_type), as a Fortran vehicle
! code would call it. bench_main.cpp times these entry points.
module creepwork_bench_fortran
   use, intrinsic :: iso_c_binding, only: c_int, c_long, c_double
   use creepwork
   implicit none
   private
   public :: cwb_fortran_create, cwb_fortran_destroy, cwb_fortran_run

   type(cw_solver_type), save :: solver
   type(cw_result), save :: result
   real(c_double), allocatable, save :: field(:, :), profile_y(:), profile_w(:), parabola(:)
   integer(c_int), allocatable, save :: state(:, :)

contains

   ! A Kalker strip grid nx x ny; returns a CW_* status.
   function cwb_fortran_create(nx, ny) bind(c, name='cwb_fortran_create') result(status)
      integer(c_int), value :: nx, ny
      integer(c_int) :: status
      integer :: stat
      call solver%create(nx=int(nx), ny=int(ny), kind=int(CW_GRID_KALKER_STRIPS), stat=stat)
      status = int(stat, c_int)
      if (stat /= CW_OK) return
      if (allocated(field)) deallocate(field, state, profile_y, profile_w, parabola)
      allocate(field(nx, ny), state(nx, ny), profile_y(ny), profile_w(ny), parabola(ny))
      call cw_result_init(result)
   end function cwb_fortran_create

   subroutine cwb_fortran_destroy() bind(c, name='cwb_fortran_destroy')
      call solver%destroy()
   end subroutine cwb_fortran_destroy

   ! reps solves of params with mode CW_SOLVE_*; with fields /= 0 each solve
   ! is followed by every field, the state map and the profile. totals gets
   ! Fx, Fy, Mz, W_macro, W_micro_paper, W_consistent of the last solve.
   ! Returns CW_OK or the first failing status.
   function cwb_fortran_run(reps, mode, fields, params, totals) &
         bind(c, name='cwb_fortran_run') result(status)
      integer(c_long), value :: reps
      integer(c_int), value :: mode, fields
      type(cw_params), intent(in) :: params
      real(c_double), intent(out) :: totals(6)
      integer(c_int) :: status
      integer(c_long) :: r
      integer :: f, stat
      stat = CW_OK
      do r = 1, reps
         call solver%solve(params, mode=int(mode), result=result, stat=stat)
         if (stat /= CW_OK) exit
         if (fields /= 0) then
            do f = CW_FIELD_X, CW_FIELD_WORK_CONSISTENT
               call solver%get_field(f, field, stat=stat)
               if (stat /= CW_OK) exit
            end do
            if (stat /= CW_OK) exit
            call solver%get_state(state, stat=stat)
            if (stat /= CW_OK) exit
            call solver%get_profile(y=profile_y, w=profile_w, parabola=parabola, stat=stat)
            if (stat /= CW_OK) exit
         end if
      end do
      status = int(stat, c_int)
      totals = [result%Fx, result%Fy, result%Mz, result%W_macro, result%W_micro_paper, &
                result%W_consistent]
   end function cwb_fortran_run

end module creepwork_bench_fortran
