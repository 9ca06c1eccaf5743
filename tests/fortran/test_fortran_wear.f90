! Wear through module creepwork and the legacy layer:
!   structs   c_sizeof of the bind(C) mirrors equals the struct_size the C
!             _init functions write; the defaults land in the right fields
!   wear      cw_wear_type on a solve: mass per distance = sum rate x area
!             (1e-12), strips, regimes, result; errors through stat/errmsg
!   profile   cw_wear_profile_type: volume kept, a state moved through
!             get_state/add_state equals merging (bitwise), update helper
!   legacy    CWWEAR equals the module's wear bitwise; CWWPRF equals the
!             module's profile for one add (bitwise) and adds in double;
!             CWWUPD equals cw_wear_profile_update; errors leave outputs
program test_fortran_wear
   use, intrinsic :: iso_c_binding, only: c_double, c_int, c_int64_t, c_sizeof
   use creepwork
   use cw_test_support
   implicit none
   include 'creepwork_legacy.fi'

   integer, parameter :: nx = 14, ny = 10, ns = 61
   real(c_double), parameter :: pi = 3.14159265358979323846_c_double

   call check_structs()
   call check_wear_and_profile()
   call check_legacy()
   call test_summary('test_fortran_wear')

contains

   subroutine check_structs()
      type(cw_wear_params) :: p
      type(cw_wear_result) :: r
      type(cw_wear_profile_totals) :: t
      call cw_wear_params_init(p)
      call cw_wear_result_init(r)
      call cw_wear_profile_totals_init(t)
      call check_int(int(p%struct_size), int(c_sizeof(p)), 'sizeof(cw_wear_params)')
      call check_int(int(r%struct_size), int(c_sizeof(r)), 'sizeof(cw_wear_result)')
      call check_int(int(t%struct_size), int(c_sizeof(t)), 'sizeof(cw_wear_profile_totals)')
      call check_int(p%law, CW_WEAR_USFD, 'default law')
      call check_same(p%density, 7800.0_c_double, 'default density')
      call check_same(p%usfd_k2, 55.0e-3_c_double, 'usfd_k2 = 55.0 ug/(m mm^2)')
      call check_same(p%usfd_c3, 4.7787_c_double, 'usfd_c3 = 4778.7 ug/(m mm^2)')
      call check_same(p%kth_v2, 0.7_c_double, 'kth_v2')
      call check_same(p%kth_k_fast, 5.5e-4_c_double, 'kth_k_fast (the last field)')
   end subroutine check_structs

   subroutine solved(solver, xi, eta, phi)
      type(cw_solver_type), intent(inout) :: solver
      real(c_double), intent(in) :: xi, eta, phi
      type(cw_params) :: p
      call cw_params_init(p)
      p%a = 6e-3_c_double
      p%b = 4e-3_c_double
      p%normal_force = 60e3_c_double
      p%mu = 0.35_c_double
      p%xi_x = xi
      p%xi_y = eta
      p%phi = phi
      call solver%solve(p, CW_SOLVE_FULL)
   end subroutine solved

   subroutine check_wear_and_profile()
      type(cw_solver_type) :: solver
      type(cw_wear_type) :: wear
      type(cw_wear_profile_type) :: pa, pb, pc
      type(cw_wear_params) :: wp
      type(cw_wear_result) :: r
      type(cw_wear_profile_totals) :: t
      real(c_double) :: rate(nx, ny), area(nx, ny), y(ny), dy(ny), d(ny), par(ny)
      real(c_double) :: s(ns), da(ns), db(ns), old(ns), new(ns)
      integer(c_int) :: regime(nx, ny)
      integer(c_int64_t), allocatable :: state(:)
      character(len=:), allocatable :: msg
      integer :: stat, k
      call solver%create(nx=nx, ny=ny)
      call solved(solver, 2e-3_c_double, -1e-3_c_double, 1.5_c_double)
      call wear%create(solver)
      call cw_wear_params_init(wp)
      wp%law = CW_WEAR_ARCHARD_KTH
      wp%rolling_speed = 25.0_c_double
      call wear%compute(solver, wp, r)
      call wear%get_field(CW_WEAR_FIELD_RATE, rate)
      call solver%get_field(CW_FIELD_AREA, area)
      call check_close(r%mass_per_distance, sum(rate*area), 1e-12_c_double, 0.0_c_double, &
                       'mass per distance = sum rate x area')
      call check_true(r%mass_per_distance > 0, 'some wear')
      call wear%get_regimes(regime)
      call check_true(all(regime >= 0 .and. regime <= 4), 'regimes 0..4')
      call wear%get_strips(y=y, width=dy, depth=d, parabola=par)
      call check_close(sum(par*dy), sum(d*dy), 1e-12_c_double, 0.0_c_double, &
                       'the parabola keeps the worn cross-section')
      ! errors through stat and errmsg, outputs untouched
      wp%hardness = -1
      call wear%compute(solver, wp, stat=stat, errmsg=msg)
      call check_int(stat, CW_ERR_INVALID_INPUT, 'hardness < 0')
      call check_true(index(msg, 'hardness') > 0, 'message names hardness: '//msg)
      rate = -1
      call wear%get_field(CW_WEAR_FIELD_RATE, rate, stat=stat)
      call check_int(stat, CW_ERR_NO_SOLUTION, 'no wear after a failed compute')
      call check_true(all(rate == -1), 'rate untouched')
      call wear%compute(solver) ! defaults: USFD
      ! profiles: two halves merged through a saved state equal one
      do k = 1, ns
         s(k) = -15e-3_c_double + 0.5e-3_c_double*(k - 1)
      end do
      call pa%create(s)
      call pb%create(s)
      call pc%create(s)
      call pa%add(wear, 1e-3_c_double, contact_angle=0.1_c_double, passes=600.0_c_double)
      call pb%add(wear, 1e-3_c_double, contact_angle=0.1_c_double, passes=250.0_c_double)
      call pc%add(wear, 1e-3_c_double, contact_angle=0.1_c_double, passes=350.0_c_double)
      allocate (state(pc%state_size()))
      call check_int(size(state), 5 + 30 + 20*ns, 'state size')
      call pc%get_state(state)
      call pb%add_state(state)
      call pa%get_depth(CW_WEAR_DEPTH_HEIGHT, da)
      call pb%get_depth(CW_WEAR_DEPTH_HEIGHT, db)
      call check_true(all(transfer(da, 1_c_int64_t, ns) == transfer(db, 1_c_int64_t, ns)), &
                      '600 passes = 250 + 350 through a saved state, bitwise')
      call pa%get_totals(t)
      call wear%get_strips(y=y, width=dy, depth=d)
      call check_close(t%volume, 600*sum(d*dy), 1e-13_c_double, 0.0_c_double, 'volume')
      call check_close(sum(da)*0.5e-3_c_double, t%volume, 1e-12_c_double, 0.0_c_double, &
                       'height depth x width = volume')
      call pa%add(wear, 1e-3_c_double, orientation=0, stat=stat, errmsg=msg)
      call check_int(stat, CW_ERR_INVALID_INPUT, 'orientation 0')
      call check_true(index(msg, 'orientation') > 0, 'message names orientation')
      call pa%merge(pc)
      call pa%get_totals(t)
      call check_same(t%passes, 950.0_c_double, 'passes after the merge')
      ! update helper
      old = 0
      call cw_wear_profile_update(s, old, da, 1e-3_c_double, new)
      call check_close(sum(old - new), sum(da), 1e-12_c_double, 0.0_c_double, &
                       'the update conserves the worn section')
      call cw_wear_profile_update(s, old, da(1:ns - 1), 0.0_c_double, new, stat=stat, errmsg=msg)
      call check_int(stat, CW_ERR_INVALID_INPUT, 'update with sizes that differ')
      call pa%destroy()
      call pb%destroy()
      call pc%destroy()
      call wear%destroy()
      call solver%destroy()
   end subroutine check_wear_and_profile

   subroutine check_legacy()
      type(cw_solver_type) :: solver
      type(cw_wear_type) :: wear
      type(cw_wear_profile_type) :: profile
      type(cw_wear_params) :: wp
      type(cw_wear_result) :: r
      real(c_double) :: ys(ny), dys(ny), depth(ny), y(ny), dy(ny), d(ny), wmass
      real(c_double) :: s(ns), pdn(ns), pdh(ns), dn(ns), dh(ns), old(ns), new(ns), new2(ns)
      integer(c_int) :: ierr
      integer :: k
      ! CWWEAR = module, Archard at 25 m/s
      call CWWEAR(6e-3_c_double, 4e-3_c_double, 60e3_c_double, 0.35_c_double, 82e9_c_double, &
                  0.28_c_double, 2e-3_c_double, -1e-3_c_double, 1.5_c_double, nx, ny, 1_c_int, &
                  25.0_c_double, ys, dys, depth, wmass, ierr)
      call check_int(int(ierr), CW_OK, 'CWWEAR')
      call solver%create(nx=nx, ny=ny)
      call solved(solver, 2e-3_c_double, -1e-3_c_double, 1.5_c_double)
      call wear%create(solver)
      call cw_wear_params_init(wp)
      wp%law = CW_WEAR_ARCHARD_KTH
      wp%rolling_speed = 25.0_c_double
      call wear%compute(solver, wp, r)
      call wear%get_strips(y=y, width=dy, depth=d)
      call check_true(all(y == ys) .and. all(dy == dys) .and. all(d == depth), &
                      'CWWEAR strips = module, bitwise')
      call check_same(wmass, r%mass_per_distance, 'CWWEAR mass = module')
      ! errors leave the outputs alone
      depth = -7
      call CWWEAR(6e-3_c_double, 4e-3_c_double, 60e3_c_double, 0.35_c_double, 82e9_c_double, &
                  0.28_c_double, 2e-3_c_double, -1e-3_c_double, 1.5_c_double, nx, ny, 1_c_int, &
                  0.0_c_double, ys, dys, depth, wmass, ierr)
      call check_int(int(ierr), CW_ERR_INVALID_INPUT, 'CWWEAR Archard with V = 0')
      call check_true(all(depth == -7), 'CWWEAR outputs untouched on error')
      ! CWWPRF = module for one add; a second add doubles in double
      do k = 1, ns
         s(k) = -15e-3_c_double + 0.5e-3_c_double*(k - 1)
      end do
      pdn = 0
      pdh = 0
      call CWWPRF(ns, s, ny, y, dy, d, 2e-3_c_double, -1_c_int, 0.3_c_double, 40.0_c_double, &
                  pdn, pdh, ierr)
      call check_int(int(ierr), CW_OK, 'CWWPRF')
      call profile%create(s)
      call profile%add(wear, 2e-3_c_double, orientation=-1, contact_angle=0.3_c_double, &
                       passes=40.0_c_double)
      call profile%get_depth(CW_WEAR_DEPTH_NORMAL, dn)
      call profile%get_depth(CW_WEAR_DEPTH_HEIGHT, dh)
      call check_true(all(pdn == dn) .and. all(pdh == dh), 'CWWPRF = module, bitwise')
      call check_close(maxval(abs(pdh*cos(0.3_c_double) - pdn)), 0.0_c_double, 0.0_c_double, &
                       1e-15_c_double*maxval(pdn), 'height = normal / cos(gamma)')
      call CWWPRF(ns, s, ny, y, dy, d, 2e-3_c_double, -1_c_int, 0.3_c_double, 40.0_c_double, &
                  pdn, pdh, ierr)
      call check_true(all(pdn == 2*dn), 'a second CWWPRF adds')
      dn = pdn
      call CWWPRF(ns, s, ny, y, dy, d, 2e-3_c_double, 0_c_int, 0.3_c_double, 40.0_c_double, &
                  pdn, pdh, ierr)
      call check_int(int(ierr), CW_ERR_INVALID_INPUT, 'CWWPRF with IORI = 0')
      call check_true(all(pdn == dn), 'CWWPRF leaves the totals on error')
      ! CWWUPD = cw_wear_profile_update
      old = 1e-3_c_double
      call CWWUPD(ns, s, old, pdh, 0.7e-3_c_double, new, ierr)
      call check_int(int(ierr), CW_OK, 'CWWUPD')
      call cw_wear_profile_update(s, old, pdh, 0.7e-3_c_double, new2)
      call check_true(all(new == new2), 'CWWUPD = cw_wear_profile_update, bitwise')
      new2 = new
      call CWWUPD(ns, s, old, pdh, -1.0_c_double, new, ierr)
      call check_int(int(ierr), CW_ERR_INVALID_INPUT, 'CWWUPD with SMOOTH < 0')
      call check_true(all(new == new2), 'CWWUPD leaves PNEW on error')
      call profile%destroy()
      call wear%destroy()
      call solver%destroy()
   end subroutine check_legacy

end program test_fortran_wear
