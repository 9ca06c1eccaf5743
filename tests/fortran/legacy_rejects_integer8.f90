! Must NOT compile with -fdefault-integer-8: default INTEGER arguments are
! then 8 bytes, and creepwork_legacy.fi spells the library's integer(c_int).
! CTest compiles it with that flag and expects "Type mismatch".
program legacy_rejects_integer8
   use, intrinsic :: iso_c_binding, only: c_double
   implicit none
   include 'creepwork_legacy.fi'
   real(c_double) :: r(2)
   integer :: n(2), ierr
   r = [1.0_c_double, 2.0_c_double]
   n = [1, 2]
   call CWTYPE(r, n, ierr)
end program legacy_rejects_integer8
