! module creepwork -- the Fortran 2003 interface of libcreepwork.
!
! Creep forces, creep moment and frictional-work distributions of a wheel
! rolling on a rail by Kalker's simplified theory (FASTSIM, 1982). This module
! mirrors the C header creepwork/creepwork.h, which is the whole contract:
!
!   * private bind(C) interfaces to every function of the C ABI (assumed-size
!     buffers followed by their c_size_t length, by value);
!   * the C structs as bind(C) derived types cw_grid, cw_params, cw_result,
!     cw_accumulation, cw_wear_params, cw_wear_result, cw_wear_profile_totals
!     (struct_size first; fill them with cw_grid_init etc.);
!   * every status code and #define of the header as a named constant,
!     generated from the header at build time (creepwork_constants.inc);
!   * public wrapper types that own a C handle: cw_solver_type,
!     cw_accumulator_type, cw_batch_type, cw_wear_type, cw_wear_profile_type.
!     Each has an explicit, idempotent destroy; the final procedure is only
!     a safety net (gfortran 12 does not finalize reliably) and copying a
!     live handle is an error.
!
! Conventions (as in the header)
!   Units    consistent, SI recommended: m, N, Pa, 1/m; work in J/m.
!   Grids    real(c_double) :: f(nx, ny): element (i, j), i along x (the
!            rolling direction, x increasing), j along y (increasing) -- the
!            C layout [i + j*nx] seen from Fortran. Arrays are filled in
!            place; no copies are made.
!   Forces   on the wheel (body 1), opposite in sign to the creepages.
!   Errors   every procedure that can fail has optional stat (integer, a
!            CW_* status) and errmsg (deferred-length character). With stat
!            absent, an error stops the program (error stop) with the message.
!            On error nothing is written to the outputs.
!   Threads  distinct objects may be used concurrently from different
!            threads; one object by one thread at a time.
module creepwork
   use, intrinsic :: iso_c_binding, only: c_int, c_size_t, c_double, c_int64_t, c_char, &
      c_ptr, c_null_ptr, c_null_char, c_associated, c_f_pointer, c_loc, c_sizeof
   implicit none
   private

   include 'creepwork_constants.inc'

   ! ---------------------------------------------------------- C structs

   ! Grid of a solver (cw_grid). Call cw_grid_init first.
   type, bind(c), public :: cw_grid
      integer(c_size_t) :: struct_size = 0
      integer(c_int) :: kind = 0          ! CW_GRID_KALKER_STRIPS or CW_GRID_UNIFORM
      integer(c_int) :: nx = 0            ! elements along x, 1..CW_MAX_GRID_CELLS
      integer(c_int) :: ny = 0            ! strips along y, 1..CW_MAX_GRID_CELLS
      real(c_double) :: box_scale = 0     ! uniform grid: S in [1, CW_MAX_BOX_SCALE]
   end type cw_grid

   ! Contact parameters (cw_params). Call cw_params_init first: it sets
   ! struct_size and the defaults (steel, mu = 0.3, a = b = 6 mm, N = 80 kN).
   type, bind(c), public :: cw_params
      integer(c_size_t) :: struct_size = 0
      real(c_double) :: a = 0             ! semi-axis along x (rolling) [m]
      real(c_double) :: b = 0             ! semi-axis along y (lateral) [m]
      real(c_double) :: normal_force = 0  ! N [N]
      real(c_double) :: mu = 0            ! friction coefficient [-]
      integer(c_int) :: flexibility = 0   ! CW_FLEX_FROM_MATERIAL or CW_FLEX_GIVEN
      integer(c_int) :: pressure = 0      ! CW_PRESSURE_PARABOLIC or CW_PRESSURE_ELLIPTIC
      real(c_double) :: G = 0             ! combined shear modulus [Pa]
      real(c_double) :: nu = 0            ! combined Poisson's ratio [-]
      real(c_double) :: L1 = 0, L2 = 0, L3 = 0 ! flexibilities [m/Pa] (CW_FLEX_GIVEN)
      real(c_double) :: xi_x = 0          ! longitudinal creepage [-]
      real(c_double) :: xi_y = 0          ! lateral creepage [-]
      real(c_double) :: phi = 0           ! spin creepage [1/m]
      integer(c_int) :: rolling_direction = 0 ! +1: leading edge at x = +a; -1: at -a
      ! appended in 1.1
      integer(c_int) :: model = 0         ! CW_MODEL_FASTSIM, CW_MODEL_EXACT, CW_MODEL_CALIBRATED
      real(c_double) :: tolerance = 0     ! exact model: relative tolerance (0: default)
      integer(c_int) :: max_iterations = 0 ! exact model: iteration bound (0: default)
      integer(c_int) :: warm_start = 0    ! exact model: 1 start from the last solution
      real(c_double) :: spin_offset = 0   ! CONTACT's facphi (CW_SPIN_OFFSET_DEFAULT: model's own)
      integer(c_int) :: flexibility_blending = 0 ! FASTSIM: 1 = CONTACT's blending of L1..L3
      ! appended in 1.2
      integer(c_int) :: exact_load = 0    ! FASTSIM, calibrated: 1 = sum(pz area) = N exactly
   end type cw_params

   ! Totals of a solve (cw_result); see the header for each field.
   type, bind(c), public :: cw_result
      integer(c_size_t) :: struct_size = 0
      real(c_double) :: Fx = 0, Fy = 0    ! creep force on the wheel [N]
      real(c_double) :: Mz = 0            ! creep moment on the wheel [N m]
      real(c_double) :: W_macro = 0       ! -(Fx xi_x + Fy xi_y + Mz phi) [J/m], paper eq. 34
      real(c_double) :: W_micro_paper = 0 ! sum of the paper's local work [J/m]
      real(c_double) :: K = 0             ! W_macro / W_micro_paper, paper eq. 39
      real(c_double) :: W_consistent = 0  ! sum of the energy-consistent map [J/m]
      real(c_double) :: balance_factor = 0
      real(c_double) :: adhesion_fraction = 0
      integer(c_int) :: n_contact = 0, n_adhesion = 0, n_slip = 0
      integer(c_int) :: work_flags = 0    ! CW_WORK_* bits
      real(c_double) :: a = 0, b = 0      ! semi-axes used [m]
      real(c_double) :: L1 = 0, L2 = 0, L3 = 0 ! flexibilities used [m/Pa]
      real(c_double) :: C11 = 0, C22 = 0, C23 = 0, C33 = 0
      real(c_double) :: profile_max_diff = 0
      real(c_double) :: profile_rms_diff = 0
      ! appended in 1.1
      integer(c_int) :: model = 0         ! the CW_MODEL_* that produced this result
      real(c_double) :: p_max = 0         ! largest element pressure [Pa]
      real(c_double) :: approach = 0      ! normal approach [m]
      integer(c_int) :: iterations = 0    ! exact model: iterations of the tangential solve
      real(c_double) :: residual = 0      ! exact model: final relative residual
   end type cw_result

   ! Running totals of an accumulator (cw_accumulation), paper eqs. 35, 37.
   type, bind(c), public :: cw_accumulation
      integer(c_size_t) :: struct_size = 0
      real(c_double) :: distance = 0      ! sum(V dt) [m]
      real(c_double) :: W_macro = 0       ! [J], eq. 35
      real(c_double) :: W_micro_paper = 0 ! [J], eq. 37
      real(c_double) :: K = 0             ! over the run, eq. 39
      real(c_double) :: W_consistent = 0  ! [J]
      integer(c_int64_t) :: steps = 0
   end type cw_accumulation

   ! ------------------------------------------------------ wrapper types

   ! Owns one cw_solver: create once, solve many times, destroy.
   type, public :: cw_solver_type
      private
      type(c_ptr) :: handle = c_null_ptr
      integer :: nx = 0, ny = 0
   contains
      procedure :: create => solver_create
      procedure :: destroy => solver_destroy
      procedure :: is_created => solver_is_created
      procedure :: grid_size => solver_grid_size
      procedure :: prepare => solver_prepare
      procedure :: solve => solver_solve
      procedure :: solve_jacobian => solver_solve_jacobian
      procedure :: get_result => solver_get_result
      procedure, private :: solver_get_field_2d, solver_get_field_1d
      generic :: get_field => solver_get_field_2d, solver_get_field_1d
      procedure, private :: solver_get_state_2d, solver_get_state_1d
      generic :: get_state => solver_get_state_2d, solver_get_state_1d
      procedure :: get_profile => solver_get_profile
      procedure :: last_error => solver_last_error
      procedure, private :: solver_assign
      generic :: assignment(=) => solver_assign
      final :: solver_finalize
   end type cw_solver_type

   ! Owns one cw_accumulator: running work totals of a simulation loop.
   type, public :: cw_accumulator_type
      private
      type(c_ptr) :: handle = c_null_ptr
      integer :: nx = 0, ny = 0
   contains
      procedure :: create => accumulator_create
      procedure :: destroy => accumulator_destroy
      procedure :: is_created => accumulator_is_created
      procedure :: reset => accumulator_reset
      procedure :: add => accumulator_add
      procedure :: get_totals => accumulator_get_totals
      procedure, private :: accumulator_get_field_2d, accumulator_get_field_1d
      generic :: get_field => accumulator_get_field_2d, accumulator_get_field_1d
      procedure :: get_strip_work => accumulator_get_strip_work
      procedure :: last_error => accumulator_last_error
      procedure, private :: accumulator_assign
      generic :: assignment(=) => accumulator_assign
      final :: accumulator_finalize
   end type cw_accumulator_type

   ! Owns one cw_batch: many independent contacts on one grid (OpenMP).
   type, public :: cw_batch_type
      private
      type(c_ptr) :: handle = c_null_ptr
   contains
      procedure :: create => batch_create
      procedure :: destroy => batch_destroy
      procedure :: is_created => batch_is_created
      procedure :: prepare => batch_prepare
      procedure :: solve => batch_solve
      procedure :: last_error => batch_last_error
      procedure, private :: batch_assign
      generic :: assignment(=) => batch_assign
      final :: batch_finalize
   end type cw_batch_type

   public :: cw_library_version_number, cw_library_abi_version, cw_version_string
   public :: cw_status_string
   public :: cw_grid_init, cw_params_init, cw_result_init, cw_accumulation_init
   public :: cw_kalker_coefficients, cw_kalker_flexibilities, cw_hertz_solve
   public :: cw_fastsim_normalised

   ! Size of the message buffers handed to the C functions that take one.
   integer, parameter :: message_capacity = 1024

   ! Status and message of a call, delivered at the end of every public
   ! procedure by the same two lines:
   !    if (present(errmsg)) errmsg = error_text(o)
   !    call deliver(o, stat)
   ! (errmsg is assigned in the public procedure itself: gfortran 12 passes
   ! an optional deferred-length dummy on to another optional one wrongly.)
   type :: outcome
      integer(c_int) :: status = CW_OK
      character(len=:), allocatable :: message
   end type outcome

   ! ------------------------------------------- raw C interfaces (private)
   ! One interface per function of creepwork.h, named capi_<name> here and
   ! bound to the C name. tests/fortran checks that the two lists agree.
   interface
      function capi_version_number() bind(c, name='cw_version_number') result(v)
         import :: c_int
         integer(c_int) :: v
      end function capi_version_number

      function capi_abi_version() bind(c, name='cw_abi_version') result(v)
         import :: c_int
         integer(c_int) :: v
      end function capi_abi_version

      function capi_version_string() bind(c, name='cw_version_string') result(s)
         import :: c_ptr
         type(c_ptr) :: s
      end function capi_version_string

      function capi_status_string(status) bind(c, name='cw_status_string') result(s)
         import :: c_int, c_ptr
         integer(c_int), value :: status
         type(c_ptr) :: s
      end function capi_status_string

      function capi_grid_init(grid) bind(c, name='cw_grid_init') result(status)
         import :: c_int, cw_grid
         type(cw_grid), intent(inout) :: grid
         integer(c_int) :: status
      end function capi_grid_init

      function capi_params_init(params) bind(c, name='cw_params_init') result(status)
         import :: c_int, cw_params
         type(cw_params), intent(inout) :: params
         integer(c_int) :: status
      end function capi_params_init

      function capi_result_init(result) bind(c, name='cw_result_init') result(status)
         import :: c_int, cw_result
         type(cw_result), intent(inout) :: result
         integer(c_int) :: status
      end function capi_result_init

      function capi_solver_create(grid, solver, message, message_len) &
         bind(c, name='cw_solver_create') result(status)
         import :: c_int, c_ptr, c_char, c_size_t, cw_grid
         type(cw_grid), intent(in) :: grid
         type(c_ptr), intent(out) :: solver
         character(kind=c_char), intent(inout) :: message(*)
         integer(c_size_t), value :: message_len
         integer(c_int) :: status
      end function capi_solver_create

      function capi_solver_destroy(solver) bind(c, name='cw_solver_destroy') result(status)
         import :: c_int, c_ptr
         type(c_ptr), value :: solver
         integer(c_int) :: status
      end function capi_solver_destroy

      function capi_solver_prepare(solver, model) bind(c, name='cw_solver_prepare') &
         result(status)
         import :: c_int, c_ptr
         type(c_ptr), value :: solver
         integer(c_int), value :: model
         integer(c_int) :: status
      end function capi_solver_prepare

      function capi_solver_grid_size(solver, nx, ny) bind(c, name='cw_solver_grid_size') &
         result(status)
         import :: c_int, c_ptr
         type(c_ptr), value :: solver
         integer(c_int), intent(out) :: nx, ny
         integer(c_int) :: status
      end function capi_solver_grid_size

      function capi_solver_solve(solver, params, mode, result) bind(c, name='cw_solver_solve') &
         result(status)
         import :: c_int, c_ptr, cw_params
         type(c_ptr), value :: solver
         type(cw_params), intent(in) :: params
         integer(c_int), value :: mode
         type(c_ptr), value :: result ! cw_result*, may be NULL
         integer(c_int) :: status
      end function capi_solver_solve

      function capi_solver_solve_jacobian(solver, params, mode, result, jacobian, &
                                          jacobian_len) &
         bind(c, name='cw_solver_solve_jacobian') result(status)
         import :: c_int, c_ptr, c_double, c_size_t, cw_params
         type(c_ptr), value :: solver
         type(cw_params), intent(in) :: params
         integer(c_int), value :: mode
         type(c_ptr), value :: result ! cw_result*, may be NULL
         real(c_double), intent(inout) :: jacobian(*)
         integer(c_size_t), value :: jacobian_len
         integer(c_int) :: status
      end function capi_solver_solve_jacobian

      function capi_solver_get_result(solver, result) bind(c, name='cw_solver_get_result') &
         result(status)
         import :: c_int, c_ptr, cw_result
         type(c_ptr), value :: solver
         type(cw_result), intent(inout) :: result
         integer(c_int) :: status
      end function capi_solver_get_result

      function capi_solver_get_field(solver, field, out, out_len) &
         bind(c, name='cw_solver_get_field') result(status)
         import :: c_int, c_ptr, c_double, c_size_t
         type(c_ptr), value :: solver
         integer(c_int), value :: field
         real(c_double), intent(inout) :: out(*)
         integer(c_size_t), value :: out_len
         integer(c_int) :: status
      end function capi_solver_get_field

      function capi_solver_get_state(solver, out, out_len) bind(c, name='cw_solver_get_state') &
         result(status)
         import :: c_int, c_ptr, c_size_t
         type(c_ptr), value :: solver
         integer(c_int), intent(inout) :: out(*)
         integer(c_size_t), value :: out_len
         integer(c_int) :: status
      end function capi_solver_get_state

      function capi_solver_get_profile(solver, y, w, parabola, len) &
         bind(c, name='cw_solver_get_profile') result(status)
         import :: c_int, c_ptr, c_size_t
         type(c_ptr), value :: solver
         type(c_ptr), value :: y, w, parabola ! double*, each may be NULL
         integer(c_size_t), value :: len
         integer(c_int) :: status
      end function capi_solver_get_profile

      function capi_solver_last_error(solver) bind(c, name='cw_solver_last_error') result(s)
         import :: c_ptr
         type(c_ptr), value :: solver
         type(c_ptr) :: s
      end function capi_solver_last_error

      function capi_accumulation_init(totals) bind(c, name='cw_accumulation_init') &
         result(status)
         import :: c_int, cw_accumulation
         type(cw_accumulation), intent(inout) :: totals
         integer(c_int) :: status
      end function capi_accumulation_init

      function capi_accumulator_create(solver, accumulator) &
         bind(c, name='cw_accumulator_create') result(status)
         import :: c_int, c_ptr
         type(c_ptr), value :: solver
         type(c_ptr), intent(out) :: accumulator
         integer(c_int) :: status
      end function capi_accumulator_create

      function capi_accumulator_destroy(accumulator) bind(c, name='cw_accumulator_destroy') &
         result(status)
         import :: c_int, c_ptr
         type(c_ptr), value :: accumulator
         integer(c_int) :: status
      end function capi_accumulator_destroy

      function capi_accumulator_reset(accumulator) bind(c, name='cw_accumulator_reset') &
         result(status)
         import :: c_int, c_ptr
         type(c_ptr), value :: accumulator
         integer(c_int) :: status
      end function capi_accumulator_reset

      function capi_accumulator_add(accumulator, solver, distance) &
         bind(c, name='cw_accumulator_add') result(status)
         import :: c_int, c_ptr, c_double
         type(c_ptr), value :: accumulator, solver
         real(c_double), value :: distance
         integer(c_int) :: status
      end function capi_accumulator_add

      function capi_accumulator_get_totals(accumulator, totals) &
         bind(c, name='cw_accumulator_get_totals') result(status)
         import :: c_int, c_ptr, cw_accumulation
         type(c_ptr), value :: accumulator
         type(cw_accumulation), intent(inout) :: totals
         integer(c_int) :: status
      end function capi_accumulator_get_totals

      function capi_accumulator_get_field(accumulator, field, out, out_len) &
         bind(c, name='cw_accumulator_get_field') result(status)
         import :: c_int, c_ptr, c_double, c_size_t
         type(c_ptr), value :: accumulator
         integer(c_int), value :: field
         real(c_double), intent(inout) :: out(*)
         integer(c_size_t), value :: out_len
         integer(c_int) :: status
      end function capi_accumulator_get_field

      function capi_accumulator_get_strip_work(accumulator, out, len) &
         bind(c, name='cw_accumulator_get_strip_work') result(status)
         import :: c_int, c_ptr, c_double, c_size_t
         type(c_ptr), value :: accumulator
         real(c_double), intent(inout) :: out(*)
         integer(c_size_t), value :: len
         integer(c_int) :: status
      end function capi_accumulator_get_strip_work

      function capi_accumulator_last_error(accumulator) &
         bind(c, name='cw_accumulator_last_error') result(s)
         import :: c_ptr
         type(c_ptr), value :: accumulator
         type(c_ptr) :: s
      end function capi_accumulator_last_error

      function capi_batch_create(grid, threads, batch, message, message_len) &
         bind(c, name='cw_batch_create') result(status)
         import :: c_int, c_ptr, c_char, c_size_t, cw_grid
         type(cw_grid), intent(in) :: grid
         integer(c_int), value :: threads
         type(c_ptr), intent(out) :: batch
         character(kind=c_char), intent(inout) :: message(*)
         integer(c_size_t), value :: message_len
         integer(c_int) :: status
      end function capi_batch_create

      function capi_batch_destroy(batch) bind(c, name='cw_batch_destroy') result(status)
         import :: c_int, c_ptr
         type(c_ptr), value :: batch
         integer(c_int) :: status
      end function capi_batch_destroy

      function capi_batch_prepare(batch, model) bind(c, name='cw_batch_prepare') &
         result(status)
         import :: c_int, c_ptr
         type(c_ptr), value :: batch
         integer(c_int), value :: model
         integer(c_int) :: status
      end function capi_batch_prepare

      function capi_batch_solve(batch, count, params, mode, results, statuses) &
         bind(c, name='cw_batch_solve') result(status)
         import :: c_int, c_ptr, c_size_t, cw_params, cw_result
         type(c_ptr), value :: batch
         integer(c_size_t), value :: count
         type(cw_params), intent(in) :: params(*)
         integer(c_int), value :: mode
         type(cw_result), intent(inout) :: results(*)
         type(c_ptr), value :: statuses ! int*, may be NULL
         integer(c_int) :: status
      end function capi_batch_solve

      function capi_batch_last_error(batch) bind(c, name='cw_batch_last_error') result(s)
         import :: c_ptr
         type(c_ptr), value :: batch
         type(c_ptr) :: s
      end function capi_batch_last_error

      function capi_kalker_coefficients(a_over_b, nu, coefficients, message, message_len) &
         bind(c, name='cw_kalker_coefficients') result(status)
         import :: c_int, c_double, c_char, c_size_t
         real(c_double), value :: a_over_b, nu
         real(c_double), intent(inout) :: coefficients(*)
         character(kind=c_char), intent(inout) :: message(*)
         integer(c_size_t), value :: message_len
         integer(c_int) :: status
      end function capi_kalker_coefficients

      function capi_kalker_flexibilities(a, b, G, nu, flexibilities, message, message_len) &
         bind(c, name='cw_kalker_flexibilities') result(status)
         import :: c_int, c_double, c_char, c_size_t
         real(c_double), value :: a, b, G, nu
         real(c_double), intent(inout) :: flexibilities(*)
         character(kind=c_char), intent(inout) :: message(*)
         integer(c_size_t), value :: message_len
         integer(c_int) :: status
      end function capi_kalker_flexibilities

      function capi_hertz_solve(A, B, normal_force, E_star, hertz, message, message_len) &
         bind(c, name='cw_hertz_solve') result(status)
         import :: c_int, c_double, c_char, c_size_t
         real(c_double), value :: A, B, normal_force, E_star
         real(c_double), intent(inout) :: hertz(*)
         character(kind=c_char), intent(inout) :: message(*)
         integer(c_size_t), value :: message_len
         integer(c_int) :: status
      end function capi_hertz_solve

      function capi_fastsim_normalised(ux, uy, fx, fy, mx, my, tol, tx, ty, message, &
                                       message_len) bind(c, name='cw_fastsim_normalised') &
         result(status)
         import :: c_int, c_double, c_char, c_size_t
         real(c_double), value :: ux, uy, fx, fy
         integer(c_int), value :: mx, my
         real(c_double), value :: tol
         real(c_double), intent(inout) :: tx, ty
         character(kind=c_char), intent(inout) :: message(*)
         integer(c_size_t), value :: message_len
         integer(c_int) :: status
      end function capi_fastsim_normalised

      ! From the C library: length of a NUL-terminated string.
      pure function c_strlen(s) bind(c, name='strlen') result(n)
         import :: c_ptr, c_size_t
         type(c_ptr), value :: s
         integer(c_size_t) :: n
      end function c_strlen
   end interface

   ! ================================================================ wear
   ! Wear laws on the work map and wear accumulated on a profile grid
   ! (header section "wear", doc/theory/wear.md). A pass is one axle passage
   ! (rail) or one wheel revolution (wheel); depths per pass [m].

   ! Wear law and its coefficients (cw_wear_params), SI units. Call
   ! cw_wear_params_init first: defaults USFD R8T/900A, energy-consistent map.
   type, bind(c), public :: cw_wear_params
      integer(c_size_t) :: struct_size = 0
      integer(c_int) :: law = 0               ! CW_WEAR_USFD or CW_WEAR_ARCHARD_KTH
      integer(c_int) :: source = 0            ! CW_WEAR_SOURCE_CONSISTENT, _PAPER, _SLIP
      real(c_double) :: density = 0           ! [kg/m^3]
      real(c_double) :: rolling_speed = 0     ! V [m/s], Archard (> 0 there)
      real(c_double) :: pass_length = 0       ! rolled distance of a pass [m] (mass per pass)
      real(c_double) :: usfd_k1 = 0, usfd_t1 = 0, usfd_k2 = 0 ! [kg/(N m)], [Pa], [kg/m^3]
      real(c_double) :: usfd_t2 = 0, usfd_k3 = 0, usfd_c3 = 0 ! [Pa], [kg/(N m)], [kg/m^3]
      real(c_double) :: hardness = 0          ! H [Pa]
      real(c_double) :: kth_v1 = 0, kth_v2 = 0 ! [m/s]
      real(c_double) :: kth_seizure_ratio = 0 ! seizure above ratio * H
      real(c_double) :: kth_k_seizure = 0, kth_k_slow = 0, kth_k_severe = 0, kth_k_fast = 0
   end type cw_wear_params

   ! Totals of one contact's wear (cw_wear_result).
   type, bind(c), public :: cw_wear_result
      integer(c_size_t) :: struct_size = 0
      real(c_double) :: mass_per_distance = 0   ! [kg/m]
      real(c_double) :: mass_per_pass = 0       ! [kg]
      real(c_double) :: volume_per_distance = 0 ! [m^3/m]
      real(c_double) :: max_depth = 0           ! largest strip depth per pass [m]
      real(c_double) :: work = 0                ! frictional work used [J/m]
      real(c_double) :: regime_area(4) = 0      ! [m^2] in regime 1..4
      integer(c_int) :: law = 0, source = 0
   end type cw_wear_result

   ! Totals of a profile accumulator (cw_wear_profile_totals).
   type, bind(c), public :: cw_wear_profile_totals
      integer(c_size_t) :: struct_size = 0
      real(c_double) :: passes = 0       ! passes added
      real(c_double) :: volume = 0       ! worn cross-section added [m^2]
      real(c_double) :: volume_lost = 0  ! part of it outside the grid [m^2]
      integer(c_int64_t) :: adds = 0
   end type cw_wear_profile_totals

   ! Owns one cw_wear: the wear of a solved contact, for one solver grid.
   type, public :: cw_wear_type
      private
      type(c_ptr) :: handle = c_null_ptr
      integer :: nx = 0, ny = 0
   contains
      procedure :: create => wear_create
      procedure :: destroy => wear_destroy
      procedure :: is_created => wear_is_created
      procedure :: compute => wear_compute
      procedure, private :: wear_get_field_2d, wear_get_field_1d
      generic :: get_field => wear_get_field_2d, wear_get_field_1d
      procedure, private :: wear_get_regimes_2d, wear_get_regimes_1d
      generic :: get_regimes => wear_get_regimes_2d, wear_get_regimes_1d
      procedure :: get_strips => wear_get_strips
      procedure :: get_result => wear_get_result
      procedure :: last_error => wear_last_error
      procedure, private :: wear_assign
      generic :: assignment(=) => wear_assign
      final :: wear_finalize
   end type cw_wear_type

   ! Owns one cw_wear_profile: wear depth accumulated on a profile grid.
   type, public :: cw_wear_profile_type
      private
      type(c_ptr) :: handle = c_null_ptr
      integer :: n = 0
   contains
      procedure :: create => profile_create
      procedure :: destroy => profile_destroy
      procedure :: is_created => profile_is_created
      procedure :: reset => profile_reset
      procedure :: add => profile_add
      procedure :: add_strips => profile_add_strips
      procedure :: get_depth => profile_get_depth
      procedure :: get_totals => profile_get_totals
      procedure :: merge => profile_merge
      procedure :: state_size => profile_state_size
      procedure :: get_state => profile_get_state
      procedure :: add_state => profile_add_state
      procedure :: last_error => profile_last_error
      procedure, private :: profile_assign
      generic :: assignment(=) => profile_assign
      final :: profile_finalize
   end type cw_wear_profile_type

   public :: cw_wear_params_init, cw_wear_result_init, cw_wear_profile_totals_init
   public :: cw_wear_profile_update

   interface
      function capi_wear_params_init(params) bind(c, name='cw_wear_params_init') result(status)
         import :: c_int, cw_wear_params
         type(cw_wear_params), intent(inout) :: params
         integer(c_int) :: status
      end function capi_wear_params_init

      function capi_wear_result_init(result) bind(c, name='cw_wear_result_init') result(status)
         import :: c_int, cw_wear_result
         type(cw_wear_result), intent(inout) :: result
         integer(c_int) :: status
      end function capi_wear_result_init

      function capi_wear_create(solver, wear) bind(c, name='cw_wear_create') result(status)
         import :: c_int, c_ptr
         type(c_ptr), value :: solver
         type(c_ptr), intent(out) :: wear
         integer(c_int) :: status
      end function capi_wear_create

      function capi_wear_destroy(wear) bind(c, name='cw_wear_destroy') result(status)
         import :: c_int, c_ptr
         type(c_ptr), value :: wear
         integer(c_int) :: status
      end function capi_wear_destroy

      function capi_wear_compute(wear, solver, params, result) bind(c, name='cw_wear_compute') &
         result(status)
         import :: c_int, c_ptr, cw_wear_params
         type(c_ptr), value :: wear, solver
         type(cw_wear_params), intent(in) :: params
         type(c_ptr), value :: result ! cw_wear_result*, may be NULL
         integer(c_int) :: status
      end function capi_wear_compute

      function capi_wear_get_field(wear, field, out, out_len) bind(c, name='cw_wear_get_field') &
         result(status)
         import :: c_int, c_ptr, c_double, c_size_t
         type(c_ptr), value :: wear
         integer(c_int), value :: field
         real(c_double), intent(inout) :: out(*)
         integer(c_size_t), value :: out_len
         integer(c_int) :: status
      end function capi_wear_get_field

      function capi_wear_get_regimes(wear, out, out_len) bind(c, name='cw_wear_get_regimes') &
         result(status)
         import :: c_int, c_ptr, c_size_t
         type(c_ptr), value :: wear
         integer(c_int), intent(inout) :: out(*)
         integer(c_size_t), value :: out_len
         integer(c_int) :: status
      end function capi_wear_get_regimes

      function capi_wear_get_strips(wear, y, width, depth, parabola, len) &
         bind(c, name='cw_wear_get_strips') result(status)
         import :: c_int, c_ptr, c_size_t
         type(c_ptr), value :: wear
         type(c_ptr), value :: y, width, depth, parabola ! double*, each may be NULL
         integer(c_size_t), value :: len
         integer(c_int) :: status
      end function capi_wear_get_strips

      function capi_wear_get_result(wear, result) bind(c, name='cw_wear_get_result') &
         result(status)
         import :: c_int, c_ptr, cw_wear_result
         type(c_ptr), value :: wear
         type(cw_wear_result), intent(inout) :: result
         integer(c_int) :: status
      end function capi_wear_get_result

      function capi_wear_last_error(wear) bind(c, name='cw_wear_last_error') result(s)
         import :: c_ptr
         type(c_ptr), value :: wear
         type(c_ptr) :: s
      end function capi_wear_last_error

      function capi_wear_profile_totals_init(totals) &
         bind(c, name='cw_wear_profile_totals_init') result(status)
         import :: c_int, cw_wear_profile_totals
         type(cw_wear_profile_totals), intent(inout) :: totals
         integer(c_int) :: status
      end function capi_wear_profile_totals_init

      function capi_wear_profile_create(s, n, profile, message, message_len) &
         bind(c, name='cw_wear_profile_create') result(status)
         import :: c_int, c_ptr, c_double, c_size_t, c_char
         real(c_double), intent(in) :: s(*)
         integer(c_size_t), value :: n
         type(c_ptr), intent(out) :: profile
         character(kind=c_char), intent(inout) :: message(*)
         integer(c_size_t), value :: message_len
         integer(c_int) :: status
      end function capi_wear_profile_create

      function capi_wear_profile_destroy(profile) bind(c, name='cw_wear_profile_destroy') &
         result(status)
         import :: c_int, c_ptr
         type(c_ptr), value :: profile
         integer(c_int) :: status
      end function capi_wear_profile_destroy

      function capi_wear_profile_reset(profile) bind(c, name='cw_wear_profile_reset') &
         result(status)
         import :: c_int, c_ptr
         type(c_ptr), value :: profile
         integer(c_int) :: status
      end function capi_wear_profile_reset

      function capi_wear_profile_add(profile, wear, s0, orientation, contact_angle, passes) &
         bind(c, name='cw_wear_profile_add') result(status)
         import :: c_int, c_ptr, c_double
         type(c_ptr), value :: profile, wear
         real(c_double), value :: s0
         integer(c_int), value :: orientation
         real(c_double), value :: contact_angle, passes
         integer(c_int) :: status
      end function capi_wear_profile_add

      function capi_wear_profile_add_strips(profile, y, width, depth, count, s0, orientation, &
                                            contact_angle, passes) &
         bind(c, name='cw_wear_profile_add_strips') result(status)
         import :: c_int, c_ptr, c_double, c_size_t
         type(c_ptr), value :: profile
         real(c_double), intent(in) :: y(*), width(*), depth(*)
         integer(c_size_t), value :: count
         real(c_double), value :: s0
         integer(c_int), value :: orientation
         real(c_double), value :: contact_angle, passes
         integer(c_int) :: status
      end function capi_wear_profile_add_strips

      function capi_wear_profile_get_depth(profile, kind, out, out_len) &
         bind(c, name='cw_wear_profile_get_depth') result(status)
         import :: c_int, c_ptr, c_double, c_size_t
         type(c_ptr), value :: profile
         integer(c_int), value :: kind
         real(c_double), intent(inout) :: out(*)
         integer(c_size_t), value :: out_len
         integer(c_int) :: status
      end function capi_wear_profile_get_depth

      function capi_wear_profile_get_totals(profile, totals) &
         bind(c, name='cw_wear_profile_get_totals') result(status)
         import :: c_int, c_ptr, cw_wear_profile_totals
         type(c_ptr), value :: profile
         type(cw_wear_profile_totals), intent(inout) :: totals
         integer(c_int) :: status
      end function capi_wear_profile_get_totals

      function capi_wear_profile_merge(into, from) bind(c, name='cw_wear_profile_merge') &
         result(status)
         import :: c_int, c_ptr
         type(c_ptr), value :: into, from
         integer(c_int) :: status
      end function capi_wear_profile_merge

      function capi_wear_profile_state_size(profile, words) &
         bind(c, name='cw_wear_profile_state_size') result(status)
         import :: c_int, c_ptr, c_size_t
         type(c_ptr), value :: profile
         integer(c_size_t), intent(out) :: words
         integer(c_int) :: status
      end function capi_wear_profile_state_size

      function capi_wear_profile_get_state(profile, state, len) &
         bind(c, name='cw_wear_profile_get_state') result(status)
         import :: c_int, c_ptr, c_int64_t, c_size_t
         type(c_ptr), value :: profile
         integer(c_int64_t), intent(inout) :: state(*)
         integer(c_size_t), value :: len
         integer(c_int) :: status
      end function capi_wear_profile_get_state

      function capi_wear_profile_add_state(profile, state, len) &
         bind(c, name='cw_wear_profile_add_state') result(status)
         import :: c_int, c_ptr, c_int64_t, c_size_t
         type(c_ptr), value :: profile
         integer(c_int64_t), intent(in) :: state(*)
         integer(c_size_t), value :: len
         integer(c_int) :: status
      end function capi_wear_profile_add_state

      function capi_wear_profile_last_error(profile) bind(c, name='cw_wear_profile_last_error') &
         result(s)
         import :: c_ptr
         type(c_ptr), value :: profile
         type(c_ptr) :: s
      end function capi_wear_profile_last_error

      function capi_wear_profile_update(s, old_profile, depth, n, smoothing, new_profile, &
                                        new_len, message, message_len) &
         bind(c, name='cw_wear_profile_update') result(status)
         import :: c_int, c_double, c_size_t, c_char
         real(c_double), intent(in) :: s(*), old_profile(*), depth(*)
         integer(c_size_t), value :: n
         real(c_double), value :: smoothing
         real(c_double), intent(inout) :: new_profile(*)
         integer(c_size_t), value :: new_len
         character(kind=c_char), intent(inout) :: message(*)
         integer(c_size_t), value :: message_len
         integer(c_int) :: status
      end function capi_wear_profile_update
   end interface

contains

   ! ============================================================ helpers

   ! Copy of a NUL-terminated C string ('' for NULL).
   function f_string(p) result(s)
      type(c_ptr), intent(in) :: p
      character(len=:), allocatable :: s
      character(kind=c_char), pointer :: chars(:)
      integer :: n, i
      if (.not. c_associated(p)) then
         s = ''
         return
      end if
      n = int(c_strlen(p))
      call c_f_pointer(p, chars, [n])
      allocate (character(len=n) :: s)
      do i = 1, n
         s(i:i) = chars(i)
      end do
   end function f_string

   ! The text of a message buffer filled by C, up to its NUL.
   function buffer_string(buffer) result(s)
      character(kind=c_char), intent(in) :: buffer(:)
      character(len=:), allocatable :: s
      integer :: n, i
      n = 0
      do while (n < size(buffer))
         if (buffer(n + 1) == c_null_char) exit
         n = n + 1
      end do
      allocate (character(len=n) :: s)
      do i = 1, n
         s(i:i) = buffer(i)
      end do
   end function buffer_string

   ! Outcome of a status with "<static message>: <detail>" (or the static
   ! message alone); success carries no message.
   function make_outcome(status, detail) result(o)
      integer(c_int), intent(in) :: status
      character(len=*), intent(in) :: detail
      type(outcome) :: o
      o%status = status
      if (status == CW_OK) then
         o%message = ''
      else
         o%message = f_string(capi_status_string(status))
         if (len(detail) > 0) o%message = o%message//': '//detail
      end if
   end function make_outcome

   ! A call on an object that was never created.
   function not_created(what) result(o)
      character(len=*), intent(in) :: what
      type(outcome) :: o
      o = make_outcome(CW_ERR_NULL_POINTER, 'the '//what//' has not been created (call create first)')
   end function not_created

   ! '' on success, else the message.
   function error_text(o) result(s)
      type(outcome), intent(in) :: o
      character(len=:), allocatable :: s
      s = o%message
   end function error_text

   ! The status to stat when present; otherwise an error stops the program
   ! with the message (success does nothing).
   subroutine deliver(o, stat)
      type(outcome), intent(in) :: o
      integer, intent(out), optional :: stat
      if (present(stat)) stat = int(o%status)
      if (o%status /= CW_OK .and. .not. present(stat)) then
         error stop 'creepwork: '//o%message
      end if
   end subroutine deliver

   ! Applies the optional grid settings of the create procedures.
   subroutine make_grid(g, grid, nx, ny, kind, box_scale)
      type(cw_grid), intent(out) :: g
      type(cw_grid), intent(in), optional :: grid
      integer, intent(in), optional :: nx, ny, kind
      real(c_double), intent(in), optional :: box_scale
      integer(c_int) :: status
      if (present(grid)) then
         g = grid
      else
         status = capi_grid_init(g)
      end if
      if (present(nx)) g%nx = int(nx, c_int)
      if (present(ny)) g%ny = int(ny, c_int)
      if (present(kind)) g%kind = int(kind, c_int)
      if (present(box_scale)) g%box_scale = box_scale
   end subroutine make_grid

   ! Decimal text of an integer. List-directed, so that no format string
   ! is parsed: libgfortran copies formats with strndup, which
   ! AddressSanitizer's strict_string_checks reports as an overflow.
   function integer_text(n) result(s)
      integer, intent(in) :: n
      character(len=:), allocatable :: s
      character(len=32) :: buffer
      write (buffer, *) n
      s = trim(adjustl(buffer))
   end function integer_text

   ! A caller's (nx, ny) map must match the grid.
   function map_shape(n1, n2, nx, ny) result(o)
      integer, intent(in) :: n1, n2, nx, ny
      type(outcome) :: o
      character(len=:), allocatable :: text
      if (n1 == nx .and. n2 == ny) then
         o = make_outcome(CW_OK, '')
         return
      end if
      text = 'out has shape ('//integer_text(n1)//', '//integer_text(n2)// &
             ') but the grid is ('//integer_text(nx)//', '//integer_text(ny)//')'
      if (n1*n2 < nx*ny) then
         o = make_outcome(CW_ERR_BUFFER_TOO_SMALL, text)
      else
         o = make_outcome(CW_ERR_INVALID_INPUT, text)
      end if
   end function map_shape

   ! ======================================================== free functions

   ! Run-time version of the loaded library: compare with CW_VERSION_NUMBER.
   function cw_library_version_number() result(v)
      integer :: v
      v = int(capi_version_number())
   end function cw_library_version_number

   ! Run-time ABI version of the loaded library: compare with CW_ABI_VERSION.
   function cw_library_abi_version() result(v)
      integer :: v
      v = int(capi_abi_version())
   end function cw_library_abi_version

   ! "1.2.0"
   function cw_version_string() result(s)
      character(len=:), allocatable :: s
      s = f_string(capi_version_string())
   end function cw_version_string

   ! Static message of a status code ("unknown status code" if not a CW_*).
   function cw_status_string(status) result(s)
      integer, intent(in) :: status
      character(len=:), allocatable :: s
      s = f_string(capi_status_string(int(status, c_int)))
   end function cw_status_string

   ! Defaults and struct_size (default grid: Kalker strips, 20 x 20).
   subroutine cw_grid_init(grid)
      type(cw_grid), intent(out) :: grid
      integer(c_int) :: status
      status = capi_grid_init(grid)
   end subroutine cw_grid_init

   ! Defaults and struct_size: steel (G = 82e9 Pa, nu = 0.28), mu = 0.3,
   ! a = b = 6e-3 m, N = 80e3 N, zero creepage, parabolic pressure, +x.
   subroutine cw_params_init(params)
      type(cw_params), intent(out) :: params
      integer(c_int) :: status
      status = capi_params_init(params)
   end subroutine cw_params_init

   ! Zeroes and sets struct_size.
   subroutine cw_result_init(result)
      type(cw_result), intent(out) :: result
      integer(c_int) :: status
      status = capi_result_init(result)
   end subroutine cw_result_init

   ! Zeroes and sets struct_size.
   subroutine cw_accumulation_init(totals)
      type(cw_accumulation), intent(out) :: totals
      integer(c_int) :: status
      status = capi_accumulation_init(totals)
   end subroutine cw_accumulation_init

   ! Kalker's coefficients C11, C22, C23, C33 (Kalker 1990, Table E.3).
   subroutine cw_kalker_coefficients(a_over_b, nu, coefficients, stat, errmsg)
      real(c_double), intent(in) :: a_over_b, nu
      real(c_double), intent(inout) :: coefficients(4)
      integer, intent(out), optional :: stat
      character(len=:), allocatable, intent(out), optional :: errmsg
      character(kind=c_char) :: buffer(message_capacity)
      type(outcome) :: o
      buffer(1) = c_null_char
      o = make_outcome(capi_kalker_coefficients(a_over_b, nu, coefficients, buffer, &
                                                size(buffer, kind=c_size_t)), buffer_string(buffer))
      if (present(errmsg)) errmsg = error_text(o)
      call deliver(o, stat)
   end subroutine cw_kalker_coefficients

   ! Flexibilities L1, L2, L3 [m/Pa] of the simplified theory.
   subroutine cw_kalker_flexibilities(a, b, G, nu, flexibilities, stat, errmsg)
      real(c_double), intent(in) :: a, b, G, nu
      real(c_double), intent(inout) :: flexibilities(3)
      integer, intent(out), optional :: stat
      character(len=:), allocatable, intent(out), optional :: errmsg
      character(kind=c_char) :: buffer(message_capacity)
      type(outcome) :: o
      buffer(1) = c_null_char
      o = make_outcome(capi_kalker_flexibilities(a, b, G, nu, flexibilities, buffer, &
                                                 size(buffer, kind=c_size_t)), buffer_string(buffer))
      if (present(errmsg)) errmsg = error_text(o)
      call deliver(o, stat)
   end subroutine cw_kalker_flexibilities

   ! Hertz contact from the undeformed gap A x^2 + B y^2 [1/m]: A and B are
   ! HALF the relative curvatures, A = (1/R1x + 1/R2x)/2 (see the header).
   ! hertz = a [m], b [m], p0 [Pa], approach [m].
   subroutine cw_hertz_solve(A, B, normal_force, E_star, hertz, stat, errmsg)
      real(c_double), intent(in) :: A, B, normal_force, E_star
      real(c_double), intent(inout) :: hertz(4)
      integer, intent(out), optional :: stat
      character(len=:), allocatable, intent(out), optional :: errmsg
      character(kind=c_char) :: buffer(message_capacity)
      type(outcome) :: o
      buffer(1) = c_null_char
      o = make_outcome(capi_hertz_solve(A, B, normal_force, E_star, hertz, buffer, &
                                        size(buffer, kind=c_size_t)), buffer_string(buffer))
      if (present(errmsg)) errmsg = error_text(o)
      call deliver(o, stat)
   end subroutine cw_hertz_solve

   ! Kalker's original normalised FASTSIM (1982): tx, ty are the forces on
   ! the rail divided by mu N (the sign of the creepages). See the header.
   subroutine cw_fastsim_normalised(ux, uy, fx, fy, mx, my, tol, tx, ty, stat, errmsg)
      real(c_double), intent(in) :: ux, uy, fx, fy
      integer, intent(in) :: mx, my
      real(c_double), intent(in) :: tol
      real(c_double), intent(inout) :: tx, ty
      integer, intent(out), optional :: stat
      character(len=:), allocatable, intent(out), optional :: errmsg
      character(kind=c_char) :: buffer(message_capacity)
      type(outcome) :: o
      buffer(1) = c_null_char
      o = make_outcome(capi_fastsim_normalised(ux, uy, fx, fy, int(mx, c_int), int(my, c_int), &
                                               tol, tx, ty, buffer, size(buffer, kind=c_size_t)), &
                       buffer_string(buffer))
      if (present(errmsg)) errmsg = error_text(o)
      call deliver(o, stat)
   end subroutine cw_fastsim_normalised

   ! ================================================================ solver

   ! Creates the solver (destroying a previous one): from grid if given
   ! (after cw_grid_init), else the defaults; nx, ny, kind, box_scale
   ! override. All memory is allocated here, none in solve.
   subroutine solver_create(self, grid, nx, ny, kind, box_scale, stat, errmsg)
      class(cw_solver_type), intent(inout) :: self
      type(cw_grid), intent(in), optional :: grid
      integer, intent(in), optional :: nx, ny, kind
      real(c_double), intent(in), optional :: box_scale
      integer, intent(out), optional :: stat
      character(len=:), allocatable, intent(out), optional :: errmsg
      type(cw_grid) :: g
      character(kind=c_char) :: buffer(message_capacity)
      integer(c_int) :: status, gnx, gny
      type(outcome) :: o
      call self%destroy()
      call make_grid(g, grid, nx, ny, kind, box_scale)
      buffer(1) = c_null_char
      status = capi_solver_create(g, self%handle, buffer, size(buffer, kind=c_size_t))
      if (status == CW_OK) then
         status = capi_solver_grid_size(self%handle, gnx, gny)
         self%nx = int(gnx)
         self%ny = int(gny)
      end if
      o = make_outcome(status, buffer_string(buffer))
      if (present(errmsg)) errmsg = error_text(o)
      call deliver(o, stat)
   end subroutine solver_create

   ! Frees the C solver; does nothing when there is none (idempotent).
   subroutine solver_destroy(self)
      class(cw_solver_type), intent(inout) :: self
      integer(c_int) :: status
      if (c_associated(self%handle)) status = capi_solver_destroy(self%handle)
      self%handle = c_null_ptr
      self%nx = 0
      self%ny = 0
   end subroutine solver_destroy

   logical function solver_is_created(self)
      class(cw_solver_type), intent(in) :: self
      solver_is_created = c_associated(self%handle)
   end function solver_is_created

   ! Grid dimensions (0, 0 before create).
   subroutine solver_grid_size(self, nx, ny)
      class(cw_solver_type), intent(in) :: self
      integer, intent(out) :: nx, ny
      nx = self%nx
      ny = self%ny
   end subroutine solver_grid_size

   ! Outcome of a call on the solver, with the handle's detailed message.
   function solver_outcome(self, status) result(o)
      class(cw_solver_type), intent(in) :: self
      integer(c_int), intent(in) :: status
      type(outcome) :: o
      if (status == CW_OK) then
         o = make_outcome(status, '')
      else
         o = make_outcome(status, f_string(capi_solver_last_error(self%handle)))
      end if
   end function solver_outcome

   ! Makes one model's memory now (cw_solver_prepare), so that its solves
   ! allocate nothing afterwards: model CW_MODEL_EXACT makes the exact
   ! model's tables and workspaces (about 2 kB per element; needs the uniform
   ! grid), CW_MODEL_FASTSIM has nothing to do. Idempotent.
   subroutine solver_prepare(self, model, stat, errmsg)
      class(cw_solver_type), intent(inout) :: self
      integer, intent(in) :: model
      integer, intent(out), optional :: stat
      character(len=:), allocatable, intent(out), optional :: errmsg
      type(outcome) :: o
      if (.not. c_associated(self%handle)) then
         o = not_created('solver')
      else
         o = solver_outcome(self, capi_solver_prepare(self%handle, int(model, c_int)))
      end if
      if (present(errmsg)) errmsg = error_text(o)
      call deliver(o, stat)
   end subroutine solver_prepare

   ! Solves one steady-rolling contact; mode CW_SOLVE_FULL (default) or
   ! CW_SOLVE_FORCES. result (optional) receives the totals; an
   ! uninitialised result (struct_size 0) is initialised first.
   subroutine solver_solve(self, params, mode, result, stat, errmsg)
      class(cw_solver_type), intent(inout) :: self
      type(cw_params), intent(in) :: params
      integer, intent(in), optional :: mode
      type(cw_result), intent(inout), optional, target :: result
      integer, intent(out), optional :: stat
      character(len=:), allocatable, intent(out), optional :: errmsg
      integer(c_int) :: m, status
      type(c_ptr) :: r
      type(outcome) :: o
      if (.not. c_associated(self%handle)) then
         o = not_created('solver')
      else
         m = CW_SOLVE_FULL
         if (present(mode)) m = int(mode, c_int)
         r = c_null_ptr
         if (present(result)) then
            if (result%struct_size == 0) call cw_result_init(result)
            r = c_loc(result)
         end if
         status = capi_solver_solve(self%handle, params, m, r)
         ! Success path without building an outcome (no allocation): this
         ! call sits in the caller's time loop.
         if (status == CW_OK) then
            if (present(stat)) stat = CW_OK
            if (present(errmsg)) errmsg = ''
            return
         end if
         o = solver_outcome(self, status)
      end if
      if (present(errmsg)) errmsg = error_text(o)
      call deliver(o, stat)
   end subroutine solver_solve

   ! solve, plus the Jacobian of the reported totals (doc/theory/jacobians.md):
   ! jacobian(r, c) = d(total r)/d(input c), r = 1..4: Fx, Fy, Mz, W_macro;
   ! c = 1..4: xi_x, xi_y, phi, normal_force; SI units. (The C ABI's
   ! row-major [4*(r-1) + (c-1)] transposed to Fortran's natural (r, c).)
   ! jacobian is written only on success.
   subroutine solver_solve_jacobian(self, params, jacobian, mode, result, stat, errmsg)
      class(cw_solver_type), intent(inout) :: self
      type(cw_params), intent(in) :: params
      real(c_double), intent(inout) :: jacobian(4, 4)
      integer, intent(in), optional :: mode
      type(cw_result), intent(inout), optional, target :: result
      integer, intent(out), optional :: stat
      character(len=:), allocatable, intent(out), optional :: errmsg
      integer(c_int) :: m, status
      type(c_ptr) :: r
      type(outcome) :: o
      real(c_double) :: row_major(4, 4)
      if (.not. c_associated(self%handle)) then
         o = not_created('solver')
      else
         m = CW_SOLVE_FORCES
         if (present(mode)) m = int(mode, c_int)
         r = c_null_ptr
         if (present(result)) then
            if (result%struct_size == 0) call cw_result_init(result)
            r = c_loc(result)
         end if
         status = capi_solver_solve_jacobian(self%handle, params, m, r, row_major, &
                                             int(CW_JACOBIAN_LEN, c_size_t))
         if (status == CW_OK) then ! no outcome on success: no allocation
            jacobian = transpose(row_major)
            if (present(stat)) stat = CW_OK
            if (present(errmsg)) errmsg = ''
            return
         end if
         o = solver_outcome(self, status)
      end if
      if (present(errmsg)) errmsg = error_text(o)
      call deliver(o, stat)
   end subroutine solver_solve_jacobian

   ! Totals of the last successful solve.
   subroutine solver_get_result(self, result, stat, errmsg)
      class(cw_solver_type), intent(in) :: self
      type(cw_result), intent(inout) :: result
      integer, intent(out), optional :: stat
      character(len=:), allocatable, intent(out), optional :: errmsg
      type(outcome) :: o
      if (.not. c_associated(self%handle)) then
         o = not_created('solver')
      else
         if (result%struct_size == 0) call cw_result_init(result)
         o = solver_outcome(self, capi_solver_get_result(self%handle, result))
      end if
      if (present(errmsg)) errmsg = error_text(o)
      call deliver(o, stat)
   end subroutine solver_get_result

   ! One field (CW_FIELD_*) of the last solve into out(nx, ny), in place.
   subroutine solver_get_field_2d(self, field, out, stat, errmsg)
      class(cw_solver_type), intent(in) :: self
      integer, intent(in) :: field
      real(c_double), intent(inout), contiguous :: out(:, :)
      integer, intent(out), optional :: stat
      character(len=:), allocatable, intent(out), optional :: errmsg
      type(outcome) :: o
      integer(c_int) :: status
      if (.not. c_associated(self%handle)) then
         o = not_created('solver')
      else if (size(out, 1) /= self%nx .or. size(out, 2) /= self%ny) then
         o = map_shape(size(out, 1), size(out, 2), self%nx, self%ny)
      else
         status = capi_solver_get_field(self%handle, int(field, c_int), out, &
                                        size(out, kind=c_size_t))
         if (status == CW_OK) then ! no outcome on success: no allocation
            if (present(stat)) stat = CW_OK
            if (present(errmsg)) errmsg = ''
            return
         end if
         o = solver_outcome(self, status)
      end if
      if (present(errmsg)) errmsg = error_text(o)
      call deliver(o, stat)
   end subroutine solver_get_field_2d

   ! The same into a vector out(nx*ny or longer), element (i, j) at i + (j-1)*nx.
   subroutine solver_get_field_1d(self, field, out, stat, errmsg)
      class(cw_solver_type), intent(in) :: self
      integer, intent(in) :: field
      real(c_double), intent(inout), contiguous :: out(:)
      integer, intent(out), optional :: stat
      character(len=:), allocatable, intent(out), optional :: errmsg
      type(outcome) :: o
      integer(c_int) :: status
      if (.not. c_associated(self%handle)) then
         o = not_created('solver')
      else
         status = capi_solver_get_field(self%handle, int(field, c_int), out, &
                                        size(out, kind=c_size_t))
         if (status == CW_OK) then ! no outcome on success: no allocation
            if (present(stat)) stat = CW_OK
            if (present(errmsg)) errmsg = ''
            return
         end if
         o = solver_outcome(self, status)
      end if
      if (present(errmsg)) errmsg = error_text(o)
      call deliver(o, stat)
   end subroutine solver_get_field_1d

   ! Element states (CW_STATE_*) into out(nx, ny).
   subroutine solver_get_state_2d(self, out, stat, errmsg)
      class(cw_solver_type), intent(in) :: self
      integer(c_int), intent(inout), contiguous :: out(:, :)
      integer, intent(out), optional :: stat
      character(len=:), allocatable, intent(out), optional :: errmsg
      type(outcome) :: o
      if (.not. c_associated(self%handle)) then
         o = not_created('solver')
      else
         o = map_shape(size(out, 1), size(out, 2), self%nx, self%ny)
         if (o%status == CW_OK) &
            o = solver_outcome(self, capi_solver_get_state(self%handle, out, size(out, kind=c_size_t)))
      end if
      if (present(errmsg)) errmsg = error_text(o)
      call deliver(o, stat)
   end subroutine solver_get_state_2d

   subroutine solver_get_state_1d(self, out, stat, errmsg)
      class(cw_solver_type), intent(in) :: self
      integer(c_int), intent(inout), contiguous :: out(:)
      integer, intent(out), optional :: stat
      character(len=:), allocatable, intent(out), optional :: errmsg
      type(outcome) :: o
      if (.not. c_associated(self%handle)) then
         o = not_created('solver')
      else
         o = solver_outcome(self, capi_solver_get_state(self%handle, out, size(out, kind=c_size_t)))
      end if
      if (present(errmsg)) errmsg = error_text(o)
      call deliver(o, stat)
   end subroutine solver_get_state_1d

   ! Lateral work profile per strip j = 1..ny (needs a CW_SOLVE_FULL solve):
   ! strip centre y [m], work per unit width w [J/m per m] and the
   ! equal-area parabola; each optional, each at least ny long.
   subroutine solver_get_profile(self, y, w, parabola, stat, errmsg)
      class(cw_solver_type), intent(in) :: self
      real(c_double), intent(inout), contiguous, target, optional :: y(:), w(:), parabola(:)
      integer, intent(out), optional :: stat
      character(len=:), allocatable, intent(out), optional :: errmsg
      type(c_ptr) :: py, pw, pp
      integer(c_size_t) :: n
      type(outcome) :: o
      if (.not. c_associated(self%handle)) then
         o = not_created('solver')
      else
         n = int(self%ny, c_size_t)
         py = c_null_ptr
         pw = c_null_ptr
         pp = c_null_ptr
         if (present(y)) then
            py = c_loc(y)
            n = min(n, size(y, kind=c_size_t))
         end if
         if (present(w)) then
            pw = c_loc(w)
            n = min(n, size(w, kind=c_size_t))
         end if
         if (present(parabola)) then
            pp = c_loc(parabola)
            n = min(n, size(parabola, kind=c_size_t))
         end if
         o = solver_outcome(self, capi_solver_get_profile(self%handle, py, pw, pp, n))
      end if
      if (present(errmsg)) errmsg = error_text(o)
      call deliver(o, stat)
   end subroutine solver_get_profile

   ! Detailed message of the last error on this solver ('' after success).
   function solver_last_error(self) result(s)
      class(cw_solver_type), intent(in) :: self
      character(len=:), allocatable :: s
      if (c_associated(self%handle)) then
         s = f_string(capi_solver_last_error(self%handle))
      else
         s = 'the solver has not been created'
      end if
   end function solver_last_error

   ! A solver owns a C handle: copying a live one would free it twice.
   subroutine solver_assign(lhs, rhs)
      class(cw_solver_type), intent(inout) :: lhs
      class(cw_solver_type), intent(in) :: rhs
      if (c_associated(rhs%handle)) &
         error stop 'creepwork: a cw_solver_type cannot be copied (pass it by reference)'
      call lhs%destroy()
   end subroutine solver_assign

   subroutine solver_finalize(self)
      type(cw_solver_type), intent(inout) :: self
      call self%destroy()
   end subroutine solver_finalize

   ! =========================================================== accumulator

   ! Creates an accumulator on the grid of solver (destroying a previous one).
   subroutine accumulator_create(self, solver, stat, errmsg)
      class(cw_accumulator_type), intent(inout) :: self
      class(cw_solver_type), intent(in) :: solver
      integer, intent(out), optional :: stat
      character(len=:), allocatable, intent(out), optional :: errmsg
      type(outcome) :: o
      call self%destroy()
      if (.not. c_associated(solver%handle)) then
         o = not_created('solver')
      else
         o = make_outcome(capi_accumulator_create(solver%handle, self%handle), '')
         if (o%status == CW_OK) then
            self%nx = solver%nx
            self%ny = solver%ny
         end if
      end if
      if (present(errmsg)) errmsg = error_text(o)
      call deliver(o, stat)
   end subroutine accumulator_create

   subroutine accumulator_destroy(self)
      class(cw_accumulator_type), intent(inout) :: self
      integer(c_int) :: status
      if (c_associated(self%handle)) status = capi_accumulator_destroy(self%handle)
      self%handle = c_null_ptr
      self%nx = 0
      self%ny = 0
   end subroutine accumulator_destroy

   logical function accumulator_is_created(self)
      class(cw_accumulator_type), intent(in) :: self
      accumulator_is_created = c_associated(self%handle)
   end function accumulator_is_created

   function accumulator_outcome(self, status) result(o)
      class(cw_accumulator_type), intent(in) :: self
      integer(c_int), intent(in) :: status
      type(outcome) :: o
      if (status == CW_OK) then
         o = make_outcome(status, '')
      else
         o = make_outcome(status, f_string(capi_accumulator_last_error(self%handle)))
      end if
   end function accumulator_outcome

   ! Back to zero totals.
   subroutine accumulator_reset(self, stat, errmsg)
      class(cw_accumulator_type), intent(inout) :: self
      integer, intent(out), optional :: stat
      character(len=:), allocatable, intent(out), optional :: errmsg
      type(outcome) :: o
      if (.not. c_associated(self%handle)) then
         o = not_created('accumulator')
      else
         o = accumulator_outcome(self, capi_accumulator_reset(self%handle))
      end if
      if (present(errmsg)) errmsg = error_text(o)
      call deliver(o, stat)
   end subroutine accumulator_reset

   ! Adds the last CW_SOLVE_FULL solve of solver for a step of length
   ! distance = V*dt [m] (paper eqs. 35 and 37).
   subroutine accumulator_add(self, solver, distance, stat, errmsg)
      class(cw_accumulator_type), intent(inout) :: self
      class(cw_solver_type), intent(in) :: solver
      real(c_double), intent(in) :: distance
      integer, intent(out), optional :: stat
      character(len=:), allocatable, intent(out), optional :: errmsg
      type(outcome) :: o
      if (.not. c_associated(self%handle)) then
         o = not_created('accumulator')
      else if (.not. c_associated(solver%handle)) then
         o = not_created('solver')
      else
         o = accumulator_outcome(self, capi_accumulator_add(self%handle, solver%handle, distance))
      end if
      if (present(errmsg)) errmsg = error_text(o)
      call deliver(o, stat)
   end subroutine accumulator_add

   ! Running totals; an uninitialised totals (struct_size 0) is initialised first.
   subroutine accumulator_get_totals(self, totals, stat, errmsg)
      class(cw_accumulator_type), intent(in) :: self
      type(cw_accumulation), intent(inout) :: totals
      integer, intent(out), optional :: stat
      character(len=:), allocatable, intent(out), optional :: errmsg
      type(outcome) :: o
      if (.not. c_associated(self%handle)) then
         o = not_created('accumulator')
      else
         if (totals%struct_size == 0) call cw_accumulation_init(totals)
         o = accumulator_outcome(self, capi_accumulator_get_totals(self%handle, totals))
      end if
      if (present(errmsg)) errmsg = error_text(o)
      call deliver(o, stat)
   end subroutine accumulator_get_totals

   ! Accumulated work map [J] (CW_FIELD_WORK_PAPER or CW_FIELD_WORK_CONSISTENT)
   ! into out(nx, ny).
   subroutine accumulator_get_field_2d(self, field, out, stat, errmsg)
      class(cw_accumulator_type), intent(in) :: self
      integer, intent(in) :: field
      real(c_double), intent(inout), contiguous :: out(:, :)
      integer, intent(out), optional :: stat
      character(len=:), allocatable, intent(out), optional :: errmsg
      type(outcome) :: o
      if (.not. c_associated(self%handle)) then
         o = not_created('accumulator')
      else
         o = map_shape(size(out, 1), size(out, 2), self%nx, self%ny)
         if (o%status == CW_OK) &
            o = accumulator_outcome(self, capi_accumulator_get_field(self%handle, int(field, c_int), &
                                                                     out, size(out, kind=c_size_t)))
      end if
      if (present(errmsg)) errmsg = error_text(o)
      call deliver(o, stat)
   end subroutine accumulator_get_field_2d

   subroutine accumulator_get_field_1d(self, field, out, stat, errmsg)
      class(cw_accumulator_type), intent(in) :: self
      integer, intent(in) :: field
      real(c_double), intent(inout), contiguous :: out(:)
      integer, intent(out), optional :: stat
      character(len=:), allocatable, intent(out), optional :: errmsg
      type(outcome) :: o
      if (.not. c_associated(self%handle)) then
         o = not_created('accumulator')
      else
         o = accumulator_outcome(self, capi_accumulator_get_field(self%handle, int(field, c_int), &
                                                                  out, size(out, kind=c_size_t)))
      end if
      if (present(errmsg)) errmsg = error_text(o)
      call deliver(o, stat)
   end subroutine accumulator_get_field_1d

   ! Accumulated energy-consistent work per strip j = 1..ny [J].
   subroutine accumulator_get_strip_work(self, out, stat, errmsg)
      class(cw_accumulator_type), intent(in) :: self
      real(c_double), intent(inout), contiguous :: out(:)
      integer, intent(out), optional :: stat
      character(len=:), allocatable, intent(out), optional :: errmsg
      type(outcome) :: o
      if (.not. c_associated(self%handle)) then
         o = not_created('accumulator')
      else
         o = accumulator_outcome(self, capi_accumulator_get_strip_work(self%handle, out, &
                                                                       size(out, kind=c_size_t)))
      end if
      if (present(errmsg)) errmsg = error_text(o)
      call deliver(o, stat)
   end subroutine accumulator_get_strip_work

   function accumulator_last_error(self) result(s)
      class(cw_accumulator_type), intent(in) :: self
      character(len=:), allocatable :: s
      if (c_associated(self%handle)) then
         s = f_string(capi_accumulator_last_error(self%handle))
      else
         s = 'the accumulator has not been created'
      end if
   end function accumulator_last_error

   subroutine accumulator_assign(lhs, rhs)
      class(cw_accumulator_type), intent(inout) :: lhs
      class(cw_accumulator_type), intent(in) :: rhs
      if (c_associated(rhs%handle)) &
         error stop 'creepwork: a cw_accumulator_type cannot be copied (pass it by reference)'
      call lhs%destroy()
   end subroutine accumulator_assign

   subroutine accumulator_finalize(self)
      type(cw_accumulator_type), intent(inout) :: self
      call self%destroy()
   end subroutine accumulator_finalize

   ! ================================================================= batch

   ! Creates a batch (destroying a previous one) on a grid as in
   ! cw_solver_type%create; threads <= 0 (default): all available cores.
   subroutine batch_create(self, grid, nx, ny, kind, box_scale, threads, stat, errmsg)
      class(cw_batch_type), intent(inout) :: self
      type(cw_grid), intent(in), optional :: grid
      integer, intent(in), optional :: nx, ny, kind
      real(c_double), intent(in), optional :: box_scale
      integer, intent(in), optional :: threads
      integer, intent(out), optional :: stat
      character(len=:), allocatable, intent(out), optional :: errmsg
      type(cw_grid) :: g
      character(kind=c_char) :: buffer(message_capacity)
      integer(c_int) :: t
      type(outcome) :: o
      call self%destroy()
      call make_grid(g, grid, nx, ny, kind, box_scale)
      t = 0
      if (present(threads)) t = int(threads, c_int)
      buffer(1) = c_null_char
      o = make_outcome(capi_batch_create(g, t, self%handle, buffer, size(buffer, kind=c_size_t)), &
                       buffer_string(buffer))
      if (present(errmsg)) errmsg = error_text(o)
      call deliver(o, stat)
   end subroutine batch_create

   subroutine batch_destroy(self)
      class(cw_batch_type), intent(inout) :: self
      integer(c_int) :: status
      if (c_associated(self%handle)) status = capi_batch_destroy(self%handle)
      self%handle = c_null_ptr
   end subroutine batch_destroy

   logical function batch_is_created(self)
      class(cw_batch_type), intent(in) :: self
      batch_is_created = c_associated(self%handle)
   end function batch_is_created

   ! cw_solver_type%prepare for the solver of every thread of the batch
   ! (cw_batch_prepare).
   subroutine batch_prepare(self, model, stat, errmsg)
      class(cw_batch_type), intent(inout) :: self
      integer, intent(in) :: model
      integer, intent(out), optional :: stat
      character(len=:), allocatable, intent(out), optional :: errmsg
      type(outcome) :: o
      integer(c_int) :: status
      if (.not. c_associated(self%handle)) then
         o = not_created('batch')
      else
         status = capi_batch_prepare(self%handle, int(model, c_int))
         if (status == CW_OK) then
            o = make_outcome(status, '')
         else
            o = make_outcome(status, f_string(capi_batch_last_error(self%handle)))
         end if
      end if
      if (present(errmsg)) errmsg = error_text(o)
      call deliver(o, stat)
   end subroutine batch_prepare

   ! Buffer of n elements where count are needed.
   function too_short(name, n, count) result(o)
      character(len=*), intent(in) :: name
      integer, intent(in) :: n, count
      type(outcome) :: o
      o = make_outcome(CW_ERR_BUFFER_TOO_SMALL, name//' holds '//integer_text(n)//' but '// &
                       integer_text(count)//' are needed')
   end function too_short

   ! Solves size(params) independent contacts into results(1:size(params))
   ! (results bitwise equal to one-by-one solves). statuses (optional)
   ! receives each contact's status. Uninitialised results are initialised.
   subroutine batch_solve(self, params, mode, results, statuses, stat, errmsg)
      class(cw_batch_type), intent(inout) :: self
      type(cw_params), intent(in), contiguous :: params(:)
      integer, intent(in) :: mode
      type(cw_result), intent(inout), contiguous :: results(:)
      integer(c_int), intent(inout), contiguous, target, optional :: statuses(:)
      integer, intent(out), optional :: stat
      character(len=:), allocatable, intent(out), optional :: errmsg
      type(c_ptr) :: ps
      type(outcome) :: o
      integer :: i
      if (.not. c_associated(self%handle)) then
         o = not_created('batch')
      else if (size(results) < size(params)) then
         o = too_short('results', size(results), size(params))
      else
         o = make_outcome(CW_OK, '')
         ps = c_null_ptr
         if (present(statuses)) then
            if (size(statuses) < size(params)) then
               o = too_short('statuses', size(statuses), size(params))
            else
               ps = c_loc(statuses)
            end if
         end if
         if (o%status == CW_OK) then
            do i = 1, size(params)
               if (results(i)%struct_size == 0) call cw_result_init(results(i))
            end do
            o%status = capi_batch_solve(self%handle, size(params, kind=c_size_t), params, &
                                        int(mode, c_int), results, ps)
            if (o%status /= CW_OK) &
               o = make_outcome(o%status, f_string(capi_batch_last_error(self%handle)))
         end if
      end if
      if (present(errmsg)) errmsg = error_text(o)
      call deliver(o, stat)
   end subroutine batch_solve

   function batch_last_error(self) result(s)
      class(cw_batch_type), intent(in) :: self
      character(len=:), allocatable :: s
      if (c_associated(self%handle)) then
         s = f_string(capi_batch_last_error(self%handle))
      else
         s = 'the batch has not been created'
      end if
   end function batch_last_error

   subroutine batch_assign(lhs, rhs)
      class(cw_batch_type), intent(inout) :: lhs
      class(cw_batch_type), intent(in) :: rhs
      if (c_associated(rhs%handle)) &
         error stop 'creepwork: a cw_batch_type cannot be copied (pass it by reference)'
      call lhs%destroy()
   end subroutine batch_assign

   subroutine batch_finalize(self)
      type(cw_batch_type), intent(inout) :: self
      call self%destroy()
   end subroutine batch_finalize

   ! ================================================================ wear

   ! Defaults and struct_size: USFD (Braghin et al. 2006, R8T/900A) on the
   ! energy-consistent map, steel density, pass_length 1 m; KTH map values.
   subroutine cw_wear_params_init(params)
      type(cw_wear_params), intent(out) :: params
      integer(c_int) :: status
      status = capi_wear_params_init(params)
   end subroutine cw_wear_params_init

   ! Zeroes and sets struct_size.
   subroutine cw_wear_result_init(result)
      type(cw_wear_result), intent(out) :: result
      integer(c_int) :: status
      status = capi_wear_result_init(result)
   end subroutine cw_wear_result_init

   ! Zeroes and sets struct_size.
   subroutine cw_wear_profile_totals_init(totals)
      type(cw_wear_profile_totals), intent(out) :: totals
      integer(c_int) :: status
      status = capi_wear_profile_totals_init(totals)
   end subroutine cw_wear_profile_totals_init

   ! Creates the wear workspace for the grid of solver (destroying a
   ! previous one).
   subroutine wear_create(self, solver, stat, errmsg)
      class(cw_wear_type), intent(inout) :: self
      class(cw_solver_type), intent(in) :: solver
      integer, intent(out), optional :: stat
      character(len=:), allocatable, intent(out), optional :: errmsg
      type(outcome) :: o
      call self%destroy()
      if (.not. c_associated(solver%handle)) then
         o = not_created('solver')
      else
         o = make_outcome(capi_wear_create(solver%handle, self%handle), '')
         if (o%status == CW_OK) then
            self%nx = solver%nx
            self%ny = solver%ny
         end if
      end if
      if (present(errmsg)) errmsg = error_text(o)
      call deliver(o, stat)
   end subroutine wear_create

   subroutine wear_destroy(self)
      class(cw_wear_type), intent(inout) :: self
      integer(c_int) :: status
      if (c_associated(self%handle)) status = capi_wear_destroy(self%handle)
      self%handle = c_null_ptr
      self%nx = 0
      self%ny = 0
   end subroutine wear_destroy

   logical function wear_is_created(self)
      class(cw_wear_type), intent(in) :: self
      wear_is_created = c_associated(self%handle)
   end function wear_is_created

   function wear_outcome(self, status) result(o)
      class(cw_wear_type), intent(in) :: self
      integer(c_int), intent(in) :: status
      type(outcome) :: o
      if (status == CW_OK) then
         o = make_outcome(status, '')
      else
         o = make_outcome(status, f_string(capi_wear_last_error(self%handle)))
      end if
   end function wear_outcome

   ! The wear of solver's last CW_SOLVE_FULL solve. params (default: the
   ! defaults of cw_wear_params_init) and result are optional; an
   ! uninitialised result (struct_size 0) is initialised first.
   subroutine wear_compute(self, solver, params, result, stat, errmsg)
      class(cw_wear_type), intent(inout) :: self
      class(cw_solver_type), intent(in) :: solver
      type(cw_wear_params), intent(in), optional :: params
      type(cw_wear_result), intent(inout), target, optional :: result
      integer, intent(out), optional :: stat
      character(len=:), allocatable, intent(out), optional :: errmsg
      type(cw_wear_params) :: p
      type(c_ptr) :: pr
      type(outcome) :: o
      if (.not. c_associated(self%handle)) then
         o = not_created('wear')
      else if (.not. c_associated(solver%handle)) then
         o = not_created('solver')
      else
         if (present(params)) then
            p = params
         else
            call cw_wear_params_init(p)
         end if
         pr = c_null_ptr
         if (present(result)) then
            if (result%struct_size == 0) call cw_wear_result_init(result)
            pr = c_loc(result)
         end if
         o = wear_outcome(self, capi_wear_compute(self%handle, solver%handle, p, pr))
      end if
      if (present(errmsg)) errmsg = error_text(o)
      call deliver(o, stat)
   end subroutine wear_compute

   ! A CW_WEAR_FIELD_* of the last compute into out(nx, ny).
   subroutine wear_get_field_2d(self, field, out, stat, errmsg)
      class(cw_wear_type), intent(in) :: self
      integer, intent(in) :: field
      real(c_double), intent(inout), contiguous :: out(:, :)
      integer, intent(out), optional :: stat
      character(len=:), allocatable, intent(out), optional :: errmsg
      type(outcome) :: o
      if (.not. c_associated(self%handle)) then
         o = not_created('wear')
      else
         o = map_shape(size(out, 1), size(out, 2), self%nx, self%ny)
         if (o%status == CW_OK) &
            o = wear_outcome(self, capi_wear_get_field(self%handle, int(field, c_int), out, &
                                                       size(out, kind=c_size_t)))
      end if
      if (present(errmsg)) errmsg = error_text(o)
      call deliver(o, stat)
   end subroutine wear_get_field_2d

   subroutine wear_get_field_1d(self, field, out, stat, errmsg)
      class(cw_wear_type), intent(in) :: self
      integer, intent(in) :: field
      real(c_double), intent(inout), contiguous :: out(:)
      integer, intent(out), optional :: stat
      character(len=:), allocatable, intent(out), optional :: errmsg
      type(outcome) :: o
      if (.not. c_associated(self%handle)) then
         o = not_created('wear')
      else
         o = wear_outcome(self, capi_wear_get_field(self%handle, int(field, c_int), out, &
                                                    size(out, kind=c_size_t)))
      end if
      if (present(errmsg)) errmsg = error_text(o)
      call deliver(o, stat)
   end subroutine wear_get_field_1d

   ! CW_WEAR_REGIME_* per element into out(nx, ny).
   subroutine wear_get_regimes_2d(self, out, stat, errmsg)
      class(cw_wear_type), intent(in) :: self
      integer(c_int), intent(inout), contiguous :: out(:, :)
      integer, intent(out), optional :: stat
      character(len=:), allocatable, intent(out), optional :: errmsg
      type(outcome) :: o
      if (.not. c_associated(self%handle)) then
         o = not_created('wear')
      else
         o = map_shape(size(out, 1), size(out, 2), self%nx, self%ny)
         if (o%status == CW_OK) &
            o = wear_outcome(self, capi_wear_get_regimes(self%handle, out, size(out, kind=c_size_t)))
      end if
      if (present(errmsg)) errmsg = error_text(o)
      call deliver(o, stat)
   end subroutine wear_get_regimes_2d

   subroutine wear_get_regimes_1d(self, out, stat, errmsg)
      class(cw_wear_type), intent(in) :: self
      integer(c_int), intent(inout), contiguous :: out(:)
      integer, intent(out), optional :: stat
      character(len=:), allocatable, intent(out), optional :: errmsg
      type(outcome) :: o
      if (.not. c_associated(self%handle)) then
         o = not_created('wear')
      else
         o = wear_outcome(self, capi_wear_get_regimes(self%handle, out, size(out, kind=c_size_t)))
      end if
      if (present(errmsg)) errmsg = error_text(o)
      call deliver(o, stat)
   end subroutine wear_get_regimes_1d

   ! The lateral wear profile per strip j = 1..ny: centre y [m], width [m],
   ! depth per pass [m] and the equal-volume parabola [m]; each optional,
   ! each at least ny long.
   subroutine wear_get_strips(self, y, width, depth, parabola, stat, errmsg)
      class(cw_wear_type), intent(in) :: self
      real(c_double), intent(inout), contiguous, target, optional :: y(:), width(:), depth(:), &
                                                                     parabola(:)
      integer, intent(out), optional :: stat
      character(len=:), allocatable, intent(out), optional :: errmsg
      type(c_ptr) :: py, pw, pd, pp
      integer(c_size_t) :: n
      type(outcome) :: o
      if (.not. c_associated(self%handle)) then
         o = not_created('wear')
      else
         n = int(self%ny, c_size_t)
         py = c_null_ptr
         pw = c_null_ptr
         pd = c_null_ptr
         pp = c_null_ptr
         if (present(y)) then
            py = c_loc(y)
            n = min(n, size(y, kind=c_size_t))
         end if
         if (present(width)) then
            pw = c_loc(width)
            n = min(n, size(width, kind=c_size_t))
         end if
         if (present(depth)) then
            pd = c_loc(depth)
            n = min(n, size(depth, kind=c_size_t))
         end if
         if (present(parabola)) then
            pp = c_loc(parabola)
            n = min(n, size(parabola, kind=c_size_t))
         end if
         o = wear_outcome(self, capi_wear_get_strips(self%handle, py, pw, pd, pp, n))
      end if
      if (present(errmsg)) errmsg = error_text(o)
      call deliver(o, stat)
   end subroutine wear_get_strips

   ! Totals of the last compute; an uninitialised result is initialised first.
   subroutine wear_get_result(self, result, stat, errmsg)
      class(cw_wear_type), intent(in) :: self
      type(cw_wear_result), intent(inout) :: result
      integer, intent(out), optional :: stat
      character(len=:), allocatable, intent(out), optional :: errmsg
      type(outcome) :: o
      if (.not. c_associated(self%handle)) then
         o = not_created('wear')
      else
         if (result%struct_size == 0) call cw_wear_result_init(result)
         o = wear_outcome(self, capi_wear_get_result(self%handle, result))
      end if
      if (present(errmsg)) errmsg = error_text(o)
      call deliver(o, stat)
   end subroutine wear_get_result

   function wear_last_error(self) result(s)
      class(cw_wear_type), intent(in) :: self
      character(len=:), allocatable :: s
      if (c_associated(self%handle)) then
         s = f_string(capi_wear_last_error(self%handle))
      else
         s = 'the wear has not been created'
      end if
   end function wear_last_error

   subroutine wear_assign(lhs, rhs)
      class(cw_wear_type), intent(inout) :: lhs
      class(cw_wear_type), intent(in) :: rhs
      if (c_associated(rhs%handle)) &
         error stop 'creepwork: a cw_wear_type cannot be copied (pass it by reference)'
      call lhs%destroy()
   end subroutine wear_assign

   subroutine wear_finalize(self)
      type(cw_wear_type), intent(inout) :: self
      call self%destroy()
   end subroutine wear_finalize

   ! Creates a profile accumulator on the nodes s [m] (strictly increasing,
   ! at least 2), destroying a previous one.
   subroutine profile_create(self, s, stat, errmsg)
      class(cw_wear_profile_type), intent(inout) :: self
      real(c_double), intent(in), contiguous :: s(:)
      integer, intent(out), optional :: stat
      character(len=:), allocatable, intent(out), optional :: errmsg
      character(kind=c_char) :: buffer(message_capacity)
      type(outcome) :: o
      call self%destroy()
      buffer(1) = c_null_char
      o = make_outcome(capi_wear_profile_create(s, size(s, kind=c_size_t), self%handle, buffer, &
                                                size(buffer, kind=c_size_t)), buffer_string(buffer))
      if (o%status == CW_OK) self%n = size(s)
      if (present(errmsg)) errmsg = error_text(o)
      call deliver(o, stat)
   end subroutine profile_create

   subroutine profile_destroy(self)
      class(cw_wear_profile_type), intent(inout) :: self
      integer(c_int) :: status
      if (c_associated(self%handle)) status = capi_wear_profile_destroy(self%handle)
      self%handle = c_null_ptr
      self%n = 0
   end subroutine profile_destroy

   logical function profile_is_created(self)
      class(cw_wear_profile_type), intent(in) :: self
      profile_is_created = c_associated(self%handle)
   end function profile_is_created

   function profile_outcome(self, status) result(o)
      class(cw_wear_profile_type), intent(in) :: self
      integer(c_int), intent(in) :: status
      type(outcome) :: o
      if (status == CW_OK) then
         o = make_outcome(status, '')
      else
         o = make_outcome(status, f_string(capi_wear_profile_last_error(self%handle)))
      end if
   end function profile_outcome

   subroutine profile_reset(self, stat, errmsg)
      class(cw_wear_profile_type), intent(inout) :: self
      integer, intent(out), optional :: stat
      character(len=:), allocatable, intent(out), optional :: errmsg
      type(outcome) :: o
      if (.not. c_associated(self%handle)) then
         o = not_created('wear profile')
      else
         o = profile_outcome(self, capi_wear_profile_reset(self%handle))
      end if
      if (present(errmsg)) errmsg = error_text(o)
      call deliver(o, stat)
   end subroutine profile_reset

   ! Adds passes (default 1) times the last compute of wear, its patch
   ! centre at s0 [m]; orientation +1 (default) or -1, contact_angle [rad]
   ! (default 0). See cw_wear_profile_add.
   subroutine profile_add(self, wear, s0, orientation, contact_angle, passes, stat, errmsg)
      class(cw_wear_profile_type), intent(inout) :: self
      class(cw_wear_type), intent(in) :: wear
      real(c_double), intent(in) :: s0
      integer, intent(in), optional :: orientation
      real(c_double), intent(in), optional :: contact_angle, passes
      integer, intent(out), optional :: stat
      character(len=:), allocatable, intent(out), optional :: errmsg
      integer(c_int) :: ori
      real(c_double) :: angle, n
      type(outcome) :: o
      ori = 1
      angle = 0
      n = 1
      if (present(orientation)) ori = int(orientation, c_int)
      if (present(contact_angle)) angle = contact_angle
      if (present(passes)) n = passes
      if (.not. c_associated(self%handle)) then
         o = not_created('wear profile')
      else if (.not. c_associated(wear%handle)) then
         o = not_created('wear')
      else
         o = profile_outcome(self, capi_wear_profile_add(self%handle, wear%handle, s0, ori, &
                                                         angle, n))
      end if
      if (present(errmsg)) errmsg = error_text(o)
      call deliver(o, stat)
   end subroutine profile_add

   ! The same from the caller's strips y, width, depth (same size).
   subroutine profile_add_strips(self, y, width, depth, s0, orientation, contact_angle, passes, &
                                 stat, errmsg)
      class(cw_wear_profile_type), intent(inout) :: self
      real(c_double), intent(in), contiguous :: y(:), width(:), depth(:)
      real(c_double), intent(in) :: s0
      integer, intent(in), optional :: orientation
      real(c_double), intent(in), optional :: contact_angle, passes
      integer, intent(out), optional :: stat
      character(len=:), allocatable, intent(out), optional :: errmsg
      integer(c_int) :: ori
      real(c_double) :: angle, n
      type(outcome) :: o
      ori = 1
      angle = 0
      n = 1
      if (present(orientation)) ori = int(orientation, c_int)
      if (present(contact_angle)) angle = contact_angle
      if (present(passes)) n = passes
      if (.not. c_associated(self%handle)) then
         o = not_created('wear profile')
      else if (size(width) /= size(y) .or. size(depth) /= size(y)) then
         o = make_outcome(CW_ERR_INVALID_INPUT, 'y, width and depth have sizes '// &
                          integer_text(size(y))//', '//integer_text(size(width))//', '// &
                          integer_text(size(depth))//': they must be equal')
      else
         o = profile_outcome(self, capi_wear_profile_add_strips(self%handle, y, width, depth, &
                                                                size(y, kind=c_size_t), s0, ori, &
                                                                angle, n))
      end if
      if (present(errmsg)) errmsg = error_text(o)
      call deliver(o, stat)
   end subroutine profile_add_strips

   ! Accumulated depth per node [m] (kind CW_WEAR_DEPTH_NORMAL or _HEIGHT).
   subroutine profile_get_depth(self, kind, out, stat, errmsg)
      class(cw_wear_profile_type), intent(in) :: self
      integer, intent(in) :: kind
      real(c_double), intent(inout), contiguous :: out(:)
      integer, intent(out), optional :: stat
      character(len=:), allocatable, intent(out), optional :: errmsg
      type(outcome) :: o
      if (.not. c_associated(self%handle)) then
         o = not_created('wear profile')
      else
         o = profile_outcome(self, capi_wear_profile_get_depth(self%handle, int(kind, c_int), &
                                                               out, size(out, kind=c_size_t)))
      end if
      if (present(errmsg)) errmsg = error_text(o)
      call deliver(o, stat)
   end subroutine profile_get_depth

   subroutine profile_get_totals(self, totals, stat, errmsg)
      class(cw_wear_profile_type), intent(in) :: self
      type(cw_wear_profile_totals), intent(inout) :: totals
      integer, intent(out), optional :: stat
      character(len=:), allocatable, intent(out), optional :: errmsg
      type(outcome) :: o
      if (.not. c_associated(self%handle)) then
         o = not_created('wear profile')
      else
         if (totals%struct_size == 0) call cw_wear_profile_totals_init(totals)
         o = profile_outcome(self, capi_wear_profile_get_totals(self%handle, totals))
      end if
      if (present(errmsg)) errmsg = error_text(o)
      call deliver(o, stat)
   end subroutine profile_get_totals

   ! self += from (same nodes), exactly.
   subroutine profile_merge(self, from, stat, errmsg)
      class(cw_wear_profile_type), intent(inout) :: self
      class(cw_wear_profile_type), intent(in) :: from
      integer, intent(out), optional :: stat
      character(len=:), allocatable, intent(out), optional :: errmsg
      type(outcome) :: o
      if (.not. c_associated(self%handle)) then
         o = not_created('wear profile')
      else if (.not. c_associated(from%handle)) then
         o = not_created('wear profile from')
      else
         o = profile_outcome(self, capi_wear_profile_merge(self%handle, from%handle))
      end if
      if (present(errmsg)) errmsg = error_text(o)
      call deliver(o, stat)
   end subroutine profile_merge

   ! Number of 64-bit words of the exact state (0 if not created).
   integer function profile_state_size(self)
      class(cw_wear_profile_type), intent(in) :: self
      integer(c_size_t) :: words
      integer(c_int) :: status
      profile_state_size = 0
      if (c_associated(self%handle)) then
         status = capi_wear_profile_state_size(self%handle, words)
         if (status == CW_OK) profile_state_size = int(words)
      end if
   end function profile_state_size

   ! The exact state into state(1:state_size()), e.g. for MPI.
   subroutine profile_get_state(self, state, stat, errmsg)
      class(cw_wear_profile_type), intent(in) :: self
      integer(c_int64_t), intent(inout), contiguous :: state(:)
      integer, intent(out), optional :: stat
      character(len=:), allocatable, intent(out), optional :: errmsg
      type(outcome) :: o
      if (.not. c_associated(self%handle)) then
         o = not_created('wear profile')
      else
         o = profile_outcome(self, capi_wear_profile_get_state(self%handle, state, &
                                                               size(state, kind=c_size_t)))
      end if
      if (present(errmsg)) errmsg = error_text(o)
      call deliver(o, stat)
   end subroutine profile_get_state

   ! Adds a state saved from an accumulator on the same nodes.
   subroutine profile_add_state(self, state, stat, errmsg)
      class(cw_wear_profile_type), intent(inout) :: self
      integer(c_int64_t), intent(in), contiguous :: state(:)
      integer, intent(out), optional :: stat
      character(len=:), allocatable, intent(out), optional :: errmsg
      type(outcome) :: o
      if (.not. c_associated(self%handle)) then
         o = not_created('wear profile')
      else
         o = profile_outcome(self, capi_wear_profile_add_state(self%handle, state, &
                                                               size(state, kind=c_size_t)))
      end if
      if (present(errmsg)) errmsg = error_text(o)
      call deliver(o, stat)
   end subroutine profile_add_state

   function profile_last_error(self) result(s)
      class(cw_wear_profile_type), intent(in) :: self
      character(len=:), allocatable :: s
      if (c_associated(self%handle)) then
         s = f_string(capi_wear_profile_last_error(self%handle))
      else
         s = 'the wear profile has not been created'
      end if
   end function profile_last_error

   subroutine profile_assign(lhs, rhs)
      class(cw_wear_profile_type), intent(inout) :: lhs
      class(cw_wear_profile_type), intent(in) :: rhs
      if (c_associated(rhs%handle)) &
         error stop 'creepwork: a cw_wear_profile_type cannot be copied (pass it by reference)'
      call lhs%destroy()
   end subroutine profile_assign

   subroutine profile_finalize(self)
      type(cw_wear_profile_type), intent(inout) :: self
      call self%destroy()
   end subroutine profile_finalize

   ! new_profile = old_profile - smooth(depth) on the nodes s (all the same
   ! size; new_profile a separate array), smoothing [m] the standard
   ! deviation of the volume-conserving Gaussian (0: none).
   subroutine cw_wear_profile_update(s, old_profile, depth, smoothing, new_profile, stat, errmsg)
      real(c_double), intent(in), contiguous :: s(:), old_profile(:), depth(:)
      real(c_double), intent(in) :: smoothing
      real(c_double), intent(inout), contiguous :: new_profile(:)
      integer, intent(out), optional :: stat
      character(len=:), allocatable, intent(out), optional :: errmsg
      character(kind=c_char) :: buffer(message_capacity)
      type(outcome) :: o
      if (size(old_profile) /= size(s) .or. size(depth) /= size(s)) then
         o = make_outcome(CW_ERR_INVALID_INPUT, 's, old_profile and depth have sizes '// &
                          integer_text(size(s))//', '//integer_text(size(old_profile))//', '// &
                          integer_text(size(depth))//': they must be equal')
      else
         buffer(1) = c_null_char
         o = make_outcome(capi_wear_profile_update(s, old_profile, depth, size(s, kind=c_size_t), &
                                                   smoothing, new_profile, &
                                                   size(new_profile, kind=c_size_t), buffer, &
                                                   size(buffer, kind=c_size_t)), &
                          buffer_string(buffer))
      end if
      if (present(errmsg)) errmsg = error_text(o)
      call deliver(o, stat)
   end subroutine cw_wear_profile_update

end module creepwork
