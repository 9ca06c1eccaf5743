! CWFMEM's memory and layer against closed forms (test_fortran_legacy_friction
! holds it against module creepwork, bit for bit):
!   memory    a slip distance far beyond the contact (1 km) keeps every
!             element at the coefficient it enters with, the static one
!             (doc/theory/friction.md, CONTACT's memory: theta -> 1), so in
!             full sliding at 20 % creepage -FX = (FMU + FE1) FN, where the
!             law alone gives mu(xi V) FN, 39 % less
!   layer     the initial slope (xi = 1e-5) falls by springs in series,
!             L1 / (L1 + HL / G3) with L1 = 8a / (3 G c11) (CWFLEX):
!             doc/theory/interface-layer.md; the exact half-space is no
!             uniform flexibility: 0.6 % above on CONTACT's tractcurv grid
!             (test_core_exact_layer), 0.8 % on this 48 x 48 grid (2.4 % on
!             24 x 24, whose 20 elements across stiffen the plain contact);
!             1.5 % asserted
program test_fortran_legacy_memory
   use, intrinsic :: iso_c_binding, only: c_double, c_int
   use creepwork
   use cw_test_support
   implicit none
   include 'creepwork_legacy.fi'

   integer(c_int), parameter :: nx = 48, ny = 48, exact = 1
   real(c_double), parameter :: a = 6e-3_c_double, b = 4e-3_c_double, fn = 60e3_c_double
   real(c_double), parameter :: g = 82e9_c_double, pnu = 0.28_c_double, box = 1.2_c_double
   real(c_double), parameter :: v = 10.0_c_double, zero = 0.0_c_double
   ! CONTACT's tractcurv law (FKIN 0.14, FEXP1 0.19, SABSH1 1.25 m/s) and layer
   ! (GG3 8200 N/mm^2, LAYTHK 1.25 mm)
   real(c_double), parameter :: fkin = 0.14_c_double, fe1 = 0.19_c_double, sh1 = 1.25_c_double
   real(c_double), parameter :: hl = 1.25e-3_c_double, g3 = 8.2e9_c_double

   call check_memory_holds_the_static_coefficient()
   call check_layer_slope()
   call test_summary('test_fortran_legacy_memory')

contains

   subroutine check_memory_holds_the_static_coefficient()
      real(c_double) :: fx, fy, fmz, fmur(3), mu_law
      integer(c_int) :: ierr
      call CWFMEM(exact, a, b, fn, fkin, g, pnu, 0.2_c_double, zero, zero, nx, ny, box, &
                  int(CW_FRICTION_EXPONENTIAL, c_int), fe1, sh1, zero, zero, v, 1e3_c_double, &
                  1e-3_c_double, zero, zero, zero, zero, fx, fy, fmz, fmur, ierr)
      call check_int(int(ierr), CW_OK, 'CWFMEM with 1 km of memory')
      mu_law = fkin + fe1 * exp(-log(2.0_c_double) * 0.2_c_double * v / sh1)
      print '(a, f9.6, a, f9.6, a, f9.6)', '  memory: -FX/FN ', -fx / fn, ', static ', fkin + fe1, &
         ', the law at xi V ', mu_law
      call check_close(-fx / fn, fkin + fe1, 1e-4_c_double, 0.0_c_double, &
                       '-FX/FN = FMU + FE1 under a long memory')
   end subroutine check_memory_holds_the_static_coefficient

   subroutine check_layer_slope()
      real(c_double) :: fx0, fx1, fy, fmz, fmur(3), fl1, fl2, fl3, series
      integer(c_int) :: ierr
      call CWFMEM(exact, a, b, fn, 0.3_c_double, g, pnu, 1e-5_c_double, zero, zero, nx, ny, box, &
                  0_c_int, zero, zero, zero, zero, zero, zero, zero, zero, zero, zero, zero, &
                  fx0, fy, fmz, fmur, ierr)
      call check_int(int(ierr), CW_OK, 'CWFMEM without the layer')
      call CWFMEM(exact, a, b, fn, 0.3_c_double, g, pnu, 1e-5_c_double, zero, zero, nx, ny, box, &
                  0_c_int, zero, zero, zero, zero, zero, zero, zero, hl, g3, zero, zero, &
                  fx1, fy, fmz, fmur, ierr)
      call check_int(int(ierr), CW_OK, 'CWFMEM with the layer')
      call CWFLEX(a, b, g, pnu, fl1, fl2, fl3, ierr)
      call check_int(int(ierr), CW_OK, 'CWFLEX')
      series = fl1 / (fl1 + hl / g3)
      print '(a, f7.4, a, f7.4)', '  layer: slope factor ', fx1 / fx0, ', springs in series ', series
      call check_close(fx1 / fx0, series, 1.5e-2_c_double, 0.0_c_double, &
                       'slope factor L1 / (L1 + h / G3)')
   end subroutine check_layer_slope

end program test_fortran_legacy_memory
