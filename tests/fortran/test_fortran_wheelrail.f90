! The wheel/rail handle through module creepwork: case A-2.2 of the
! Manchester benchmark from the profile files (the directory is the first
! argument), right wheel at y_ws = 3 mm, 10 kN: CONTACT's module 1 prints FN
! 9774 N, FX -417.5 N, FS -2902 N, p_max 713.2 N/mm^2, z_ws 0.1143 mm
! (examples/mbench_a22_right.ref_out); forces within 1 % of the load, p_max
! within 3 %. The patch's pressure adds up to FN (its definition), and its
! wear on a rail grid to passes x the wear's volume per distance. Then the
! height prescribed gives the same forces, and errors name their input
! through stat and errmsg (also the appended memory and layer fields).
program test_fortran_wheelrail
   use, intrinsic :: iso_c_binding, only: c_double
   use creepwork
   use cw_test_support
   implicit none

   character(len=1024) :: dir
   type(cw_wheelrail_type) :: w
   type(cw_wheelrail_params) :: p
   type(cw_wheelrail_motion) :: m
   type(cw_wheelrail_totals) :: t, h
   type(cw_wheelrail_patch) :: pa
   type(cw_wear_profile_type) :: rail
   type(cw_wear_params) :: law
   type(cw_wear_result) :: worn
   type(cw_wear_profile_totals) :: wt
   real(c_double), allocatable :: area(:), pz(:), nodes(:), py(:), pzz(:)
   integer :: i
   character(len=:), allocatable :: errmsg
   integer :: stat

   call get_command_argument(1, dir)
   call cw_wheelrail_params_init(p)
   p%side = CW_WHEELRAIL_RIGHT
   call w%create(trim(dir)//'/MBench_UIC60_v3.prr', trim(dir)//'/MBench_S1002_v3.prw', p)
   call check_true(w%is_created(), 'created')
   call cw_wheelrail_motion_init(m)
   m%y = 3.0e-3_c_double
   m%yaw = 0.0072_c_double
   m%roll = -0.00018030_c_double
   m%vs = 2.0_c_double
   m%vpitch = -4.34515030_c_double
   call w%solve(m, t, Fz=1e4_c_double)
   call check_int(int(t%n_patches), 1, 'patches')
   call check_close(t%z, 0.1143e-3_c_double, 0.0_c_double, 0.05e-6_c_double, 'z_ws')
   call check_close(t%Fz, 1e4_c_double, 1e-6_c_double, 0.0_c_double, 'Fz')
   call w%get_patch(1, pa)
   call check_close(pa%Fn, 9774.0_c_double, 0.0_c_double, 100.0_c_double, 'Fn')
   call check_close(pa%Fx, -417.5_c_double, 0.0_c_double, 100.0_c_double, 'Fx')
   call check_close(pa%Fs, -2902.0_c_double, 0.0_c_double, 100.0_c_double, 'Fs')
   call check_close(pa%p_max, 713.2e6_c_double, 0.03_c_double, 0.0_c_double, 'p_max')

   allocate (area(pa%field_nx*pa%field_ny), pz(pa%field_nx*pa%field_ny))
   call w%get_patch_field(1, CW_FIELD_AREA, area)
   call w%get_patch_field(1, CW_FIELD_PZ, pz)
   call check_close(sum(area*pz), pa%Fn, 1e-12_c_double, 0.0_c_double, 'pressure adds up to Fn')
   allocate (nodes(801))
   nodes = [(-0.04_c_double + 1e-4_c_double*i, i = 0, 800)]
   call rail%create(nodes)
   call cw_wear_params_init(law)
   call w%add_wear(law, 1e3_c_double, rail=rail, result=worn)
   call rail%get_totals(wt)
   call check_close(wt%volume, 1e3_c_double*worn%volume_per_distance, 1e-12_c_double, 0.0_c_double, &
                    'rail wear volume')
   call check_true(worn%volume_per_distance > 0, 'the patch wears')
   call w%get_patch_field(0, CW_FIELD_PZ, pz, stat=stat, errmsg=errmsg)
   call check_int(stat, int(CW_ERR_INVALID_INPUT), 'patch 0: stat')
   call check_true(index(errmsg, 'k = 0') > 0, 'patch 0 named: '//errmsg)
   call w%get_patch_field(1, CW_FIELD_PZ, pz(1:3), stat=stat)
   call check_int(stat, int(CW_ERR_BUFFER_TOO_SMALL), 'short buffer: stat')
   call rail%destroy()
   ! the rail's profile in track coordinates passes through the contact point
   call w%get_profile(CW_WHEELRAIL_RAIL, py, pzz)
   call check_true(size(py) > 100 .and. size(pzz) == size(py), 'rail profile points')
   call check_true(minval(hypot(py - pa%y_contact, pzz - pa%z_contact)) < 1e-3_c_double, &
                   'rail profile near the contact point')

   m%z = t%z
   call w%solve(m, h)
   call check_int(int(h%evaluations), 1, 'height prescribed: one evaluation')
   call check_close(h%Fz, t%Fz, 1e-6_c_double, 0.0_c_double, 'height prescribed: Fz')

   call w%get_patch(2, pa, stat=stat, errmsg=errmsg)
   call check_int(stat, int(CW_ERR_INVALID_INPUT), 'patch 2: stat')
   call check_true(index(errmsg, 'k = 1') > 0, 'patch 2 named: '//errmsg)
   call w%solve(m, t, Fz=-1.0_c_double, stat=stat, errmsg=errmsg)
   call check_int(stat, int(CW_ERR_INVALID_INPUT), 'negative Fz: stat')
   call check_true(index(errmsg, 'Fz') > 0, 'Fz named: '//errmsg)
   call w%destroy()
   call w%destroy()
   ! the interface layer's fields of type(cw_wheelrail_params), checked at create
   p%layer_h = 1.25e-3_c_double
   call w%create(trim(dir)//'/MBench_UIC60_v3.prr', trim(dir)//'/MBench_S1002_v3.prw', p, &
                 stat=stat, errmsg=errmsg)
   call check_int(stat, int(CW_ERR_INVALID_INPUT), 'a layer without its modulus: stat')
   call check_true(index(errmsg, 'layer_G') > 0, 'layer_G named: '//errmsg)
   p%layer_h = 0.0_c_double
   p%memory_s0 = -1.0_c_double
   call w%create(trim(dir)//'/MBench_UIC60_v3.prr', trim(dir)//'/MBench_S1002_v3.prw', p, &
                 stat=stat, errmsg=errmsg)
   call check_int(stat, int(CW_ERR_INVALID_INPUT), 'a negative memory_s0: stat')
   call check_true(index(errmsg, 'memory_s0') > 0, 'memory_s0 named: '//errmsg)
   call w%create('no/such/rail.prr', trim(dir)//'/MBench_S1002_v3.prw', stat=stat, errmsg=errmsg)
   call check_int(stat, int(CW_ERR_INVALID_INPUT), 'missing file: stat')
   call check_true(index(errmsg, 'no/such/rail.prr') > 0, 'file named: '//errmsg)
   call check_true(.not. w%is_created(), 'not created after an error')
   ! A main program's allocatables are never freed for it (LeakSanitizer).
   deallocate (errmsg, area, pz, nodes, py, pzz)
   call test_summary('test_fortran_wheelrail')
end program test_fortran_wheelrail
