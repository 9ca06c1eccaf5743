! module creepwork -- the Fortran 2003 interface of libcreepwork.
!
! Creep forces, creep moment and frictional-work distributions of a wheel
! rolling on a rail by Kalker's simplified theory (FASTSIM, 1982), Kalker's
! exact theory and a calibrated simplified model. This module mirrors the C
! header creepwork/creepwork.h, which is the whole contract:
!
!   * the C structs as bind(C) derived types cw_grid, cw_params, cw_result,
!     cw_accumulation, cw_wear_params, cw_wear_result, cw_wear_profile_totals,
!     cw_temperature_params, cw_temperature_result, cw_damage_params,
!     cw_damage_result, cw_transient_input, cw_transient_result (struct_size first; fill them with cw_grid_init etc.), and every status
!     code and #define of the header as a named constant -- both generated
!     from the header at build time (creepwork_types, in creepwork_c.f90);
!   * free procedures (creepwork_functions.f90): versions, cw_status_string,
!     the _init procedures, Kalker's coefficients and flexibilities, Hertz,
!     Kalker's normalised FASTSIM, the wear-profile update; and the policy
!     every door shares (creepwork_checks.f90): cw_params_check (inputs that
!     look like a unit mistake, or left at their placeholders),
!     cw_temperature_params_check and cw_damage_params_check (the surface
!     post-processors' parameters), cw_check_text,
!     cw_grid_init_model (a model's default grid), cw_input_name;
!   * wrapper types that own a C handle (one file each, all extending
!     cw_handle of creepwork_handle.f90): cw_solver_type, cw_batch_type,
!     cw_accumulator_type, cw_wear_type, cw_wear_profile_type,
!     cw_temperature_type and cw_damage_type (creepwork_surface.f90, with
!     the _init procedures of their structs), cw_wheelrail_type
!     (creepwork_wheelrail.f90, with the _init procedures of its structs),
!     cw_transient_type (creepwork_transient.f90: transient rolling, step /
!     commit / rewind / save / restore, with the _init procedures of
!     cw_transient_input and cw_transient_result). Each has
!     create, an explicit, idempotent destroy, is_created, last_error and
!     noun (its name in messages: 'solver', ...); the final procedure is only
!     a safety net (gfortran 12 does not finalize reliably) and copying a
!     live handle is an error.
!   The bind(C) interfaces to the C functions are generated too and private
!   to the library (creepwork_capi): every one is wrapped here.
!
! Conventions (as in the header)
!   Units    consistent, SI recommended: m, N, Pa, 1/m; work in J/m.
!   Grids    real(c_double) :: f(nx, ny): element (i, j), i along x (the
!            rolling direction, x increasing), j along y (increasing) -- the
!            C layout [i + j*nx] seen from Fortran. Arrays are filled in
!            place; no copies are made.
!   Forces   on the wheel (body 1), opposite in sign to the creepages.
!   Errors   every procedure that can fail has the optional arguments stat
!            (integer: a CW_* status) and errmsg, which must be declared
!               character(len=:), allocatable :: errmsg
!            (deferred length: the message gets exactly its length; a fixed
!            character(len=256) does not compile, as errmsg= must be
!            allocatable). With stat absent, an error stops the program
!            (error stop) with the message. On error nothing is written to
!            the outputs.
!   Threads  distinct objects may be used concurrently from different
!            threads; one object by one thread at a time. (gfortran 12
!            keeps the length of a deferred-length character function
!            result in a static variable where the function is called:
!            two threads calling last_error, cw_status_string or
!            cw_version_string at the same moment race in the caller's
!            code; errmsg= has no such problem.)
module creepwork
   use creepwork_types
   use creepwork_functions, only: cw_library_version_number, cw_library_abi_version, &
                                  cw_version_string, cw_status_string, cw_grid_init, &
                                  cw_params_init, cw_result_init, cw_accumulation_init, &
                                  cw_wear_params_init, cw_wear_result_init, &
                                  cw_wear_profile_totals_init, cw_kalker_coefficients, &
                                  cw_kalker_flexibilities, cw_hertz_solve, cw_fastsim_normalised, &
                                  cw_wear_profile_update, cw_friction_polach
   use creepwork_checks, only: cw_check_init, cw_params_check, cw_check_text, cw_grid_init_model, &
                               cw_input_name, cw_temperature_params_check, cw_damage_params_check
   use creepwork_solver, only: cw_solver_type
   use creepwork_batch, only: cw_batch_type
   use creepwork_accumulator, only: cw_accumulator_type
   use creepwork_wear, only: cw_wear_type, cw_wear_profile_type
   use creepwork_surface, only: cw_temperature_type, cw_damage_type, cw_temperature_params_init, &
                                cw_temperature_result_init, cw_damage_params_init, &
                                cw_damage_result_init
   use creepwork_wheelrail, only: cw_wheelrail_type, cw_wheelrail_params_init, &
                                  cw_wheelrail_motion_init, cw_wheelrail_totals_init, &
                                  cw_wheelrail_patch_init
   use creepwork_transient, only: cw_transient_type, cw_transient_input_init, &
                                  cw_transient_result_init
   implicit none
   public
end module creepwork
