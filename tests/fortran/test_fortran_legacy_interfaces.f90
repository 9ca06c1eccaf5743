! The legacy layer called through creepwork_legacy.fi, the installed
! interface blocks: every routine with the kinds the blocks spell out
! (c_double, c_int). It compiles only if the blocks match the calls, and its
! results must equal the module's (bitwise: the same library calls). The
! companion checks in CMakeLists.txt show the blocks reject a REAL and a
! default INTEGER made 8 bytes at compile time.
program legacy_interfaces
   use, intrinsic :: iso_c_binding, only: c_double, c_int
   use creepwork, only: cw_kalker_coefficients, cw_kalker_flexibilities, cw_hertz_solve, &
                        cw_fastsim_normalised, cw_status_string
   use cw_test_support
   implicit none
   include 'creepwork_legacy.fi'
   integer(c_int), parameter :: nx = 9, ny = 8
   real(c_double), dimension(nx, ny) :: px, py, sx, sy, zmap, wpap, wcon, wpacc, wcacc
   integer(c_int) :: istate(nx, ny), n(2), ierr, nwarn
   real(c_double) :: r(2), c(4), L(3), h(4), fx, fy, fmz, wmac, wmic, ck, tx, ty, tx2, ty2
   real(c_double) :: c11, c22, c23, c33, fl1, fl2, fl3, a, b, p0, appr
   real(c_double) :: dsum, wmsum, wpsum, ckrun
   character(len=200) :: msg

   r = [1.0_c_double, 2.0_c_double]
   n = [1_c_int, 2_c_int]
   ierr = -1
   call CWTYPE(r, n, ierr)
   call check_int(int(ierr), 0, 'CWTYPE')

   ! CWCHEK: the module's cw_params_check of the same contact, its message.
   call CWCHEK(7.2_c_double, 5e-3_c_double, 8e4_c_double, 0.3_c_double, 82e9_c_double, &
               0.28_c_double, 1e-3_c_double, 0.0_c_double, 0.0_c_double, 1_c_int, msg, nwarn, ierr)
   call check_int(int(ierr), 0, 'CWCHEK')
   call check_int(int(nwarn), 1, 'CWCHEK findings')
   call check_string(trim(msg), 'a = 7.2 m is implausible for a wheel-rail contact: semi-axes are '// &
                     '1-20 mm (were millimetres typed as metres?)', 'CWCHEK message')

   call CWKALK(1.5_c_double, 0.28_c_double, c11, c22, c23, c33, ierr)
   call cw_kalker_coefficients(1.5_c_double, 0.28_c_double, c)
   call check_int(int(ierr), 0, 'CWKALK')
   call check_same(c11, c(1), 'CWKALK C11')
   call check_same(c33, c(4), 'CWKALK C33')

   call CWFLEX(6e-3_c_double, 4e-3_c_double, 82e9_c_double, 0.28_c_double, fl1, fl2, fl3, ierr)
   call cw_kalker_flexibilities(6e-3_c_double, 4e-3_c_double, 82e9_c_double, 0.28_c_double, L)
   call check_int(int(ierr), 0, 'CWFLEX')
   call check_same(fl3, L(3), 'CWFLEX L3')

   call CWHERT(0.8_c_double, 1.9_c_double, 7e4_c_double, 1.1e11_c_double, a, b, p0, appr, ierr)
   call cw_hertz_solve(0.8_c_double, 1.9_c_double, 7e4_c_double, 1.1e11_c_double, h)
   call check_int(int(ierr), 0, 'CWHERT')
   call check_same(a, h(1), 'CWHERT a')
   call check_same(appr, h(4), 'CWHERT approach')

   call CWFSIM(0.4_c_double, -0.3_c_double, 0.2_c_double, 0.3_c_double, 7_c_int, 7_c_int, &
               1e-3_c_double, tx, ty, ierr)
   call cw_fastsim_normalised(0.4_c_double, -0.3_c_double, 0.2_c_double, 0.3_c_double, 7, 7, &
                              1e-3_c_double, tx2, ty2)
   call check_int(int(ierr), 0, 'CWFSIM')
   call check_same(tx, tx2, 'CWFSIM tx')

   call CWSOLM(6e-3_c_double, 4e-3_c_double, 8e4_c_double, 0.3_c_double, 82e9_c_double, &
               0.28_c_double, 1e-3_c_double, 2e-4_c_double, 0.5_c_double, nx, ny, fx, fy, fmz, &
               wmac, wmic, ck, px, py, sx, sy, zmap, wpap, wcon, istate, ierr)
   call check_int(int(ierr), 0, 'CWSOLM')
   call CWSOLL(6e-3_c_double, 4e-3_c_double, 8e4_c_double, 0.3_c_double, L(1), L(2), L(3), &
               1e-3_c_double, 2e-4_c_double, 0.5_c_double, nx, ny, tx, ty, fmz, wmac, wmic, &
               ck, px, py, sx, sy, zmap, wpap, wcon, istate, ierr)
   call check_int(int(ierr), 0, 'CWSOLL')
   call check_same(tx, fx, 'CWSOLL = CWSOLM')

   dsum = 0
   wmsum = 0
   wpsum = 0
   wpacc = 0
   wcacc = 0
   call CWACCU(nx, ny, 0.5_c_double, wmac, wmic, wpap, wcon, dsum, wmsum, wpsum, wpacc, wcacc, &
               ckrun, ierr)
   call check_int(int(ierr), 0, 'CWACCU')
   call check_close(sum(wcacc), wmsum, 1e-12_c_double, 0.0_c_double, 'CWACCU')

   call CWERRM(9_c_int, msg)
   call check_true(msg == cw_status_string(9), 'CWERRM')
   call test_summary('legacy layer through creepwork_legacy.fi')
end program legacy_interfaces
