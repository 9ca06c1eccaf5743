! Must NOT compile: a REAL (single precision) passed to a legacy routine
! through creepwork_legacy.fi. CTest expects the compiler's "Type mismatch".
program legacy_rejects_real
   use, intrinsic :: iso_c_binding, only: c_double, c_int
   implicit none
   include 'creepwork_legacy.fi'
   real :: ga
   real(c_double) :: a, b, p0, appr
   integer(c_int) :: ierr
   ga = 0.8
   call CWHERT(ga, 1.9_c_double, 7e4_c_double, 1.1e11_c_double, a, b, p0, appr, ierr)
end program legacy_rejects_real
