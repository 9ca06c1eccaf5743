! Without stat, an error stops the program with the message (CONTRIBUTING.md,
! Fortran): CTest runs this program once per case and looks for the message.
!   invalid  a solve with a = -1: "creepwork: an input value is invalid ... a = -1"
!   copy     assigning a live solver: "creepwork: a cw_solver_type cannot be copied"
program test_fortran_error_stop
   use, intrinsic :: iso_c_binding, only: c_double
   use creepwork
   use cw_test_support, only: command_argument
   implicit none
   type(cw_solver_type) :: s, t
   type(cw_params) :: p
   character(len=:), allocatable :: which
   which = command_argument(1)
   call s%create(nx=4, ny=4)
   call cw_params_init(p)
   select case (which)
   case ('invalid')
      p%a = -1.0_c_double
      call s%solve(p)
   case ('copy')
      t = s
   end select
   write (*, '(a)') 'no error stop happened'
end program test_fortran_error_stop
