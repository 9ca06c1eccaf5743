! Assertions shared by the Fortran tests: each check prints what failed
! with both values, and test_summary stops with a non-zero exit code when
! any check failed.
module cw_test_support
   use, intrinsic :: iso_c_binding, only: c_double
   implicit none
   private
   public :: check_close, check_same, check_int, check_true, check_string
   public :: test_summary, command_argument

   integer, save :: n_checks = 0, n_failures = 0

contains

   ! |actual - expected| <= atol + rtol*|expected|
   subroutine check_close(actual, expected, rtol, atol, what)
      real(c_double), intent(in) :: actual, expected, rtol, atol
      character(len=*), intent(in) :: what
      n_checks = n_checks + 1
      if (.not. (abs(actual - expected) <= atol + rtol*abs(expected))) then
         n_failures = n_failures + 1
         write (*, '(a,a)') 'FAIL ', what
         write (*, '(a,es25.17,a,es25.17,a,es9.2,a,es9.2)') '     ', actual, ' vs ', expected, &
            '  diff ', abs(actual - expected), '  allowed ', atol + rtol*abs(expected)
      end if
   end subroutine check_close

   ! Bitwise equal doubles (the same computation reached by two paths).
   subroutine check_same(actual, expected, what)
      real(c_double), intent(in) :: actual, expected
      character(len=*), intent(in) :: what
      n_checks = n_checks + 1
      if (.not. (actual == expected)) then
         n_failures = n_failures + 1
         write (*, '(a,a)') 'FAIL (not identical) ', what
         write (*, '(a,es25.17,a,es25.17)') '     ', actual, ' vs ', expected
      end if
   end subroutine check_same

   subroutine check_int(actual, expected, what)
      integer, intent(in) :: actual, expected
      character(len=*), intent(in) :: what
      n_checks = n_checks + 1
      if (actual /= expected) then
         n_failures = n_failures + 1
         write (*, '(a,a,a,i0,a,i0)') 'FAIL ', what, ': ', actual, ' vs ', expected
      end if
   end subroutine check_int

   subroutine check_true(condition, what)
      logical, intent(in) :: condition
      character(len=*), intent(in) :: what
      n_checks = n_checks + 1
      if (.not. condition) then
         n_failures = n_failures + 1
         write (*, '(a,a)') 'FAIL ', what
      end if
   end subroutine check_true

   subroutine check_string(actual, expected, what)
      character(len=*), intent(in) :: actual, expected
      character(len=*), intent(in) :: what
      n_checks = n_checks + 1
      if (actual /= expected .or. len(actual) /= len(expected)) then
         n_failures = n_failures + 1
         write (*, '(a,a,a,a,a,a,a)') 'FAIL ', what, ': "', actual, '" vs "', expected, '"'
      end if
   end subroutine check_string

   subroutine test_summary(name)
      character(len=*), intent(in) :: name
      write (*, '(a,a,i0,a,i0,a)') name, ': ', n_checks, ' checks, ', n_failures, ' failed'
      if (n_failures > 0) error stop 1
   end subroutine test_summary

   ! The n-th command-line argument (the tests get file paths this way).
   function command_argument(n) result(s)
      integer, intent(in) :: n
      character(len=:), allocatable :: s
      integer :: length, status
      call get_command_argument(n, length=length, status=status)
      if (status /= 0) then
         write (*, '(a,i0)') 'missing command-line argument ', n
         error stop 2
      end if
      allocate (character(len=length) :: s)
      call get_command_argument(n, s)
   end function command_argument

end module cw_test_support
