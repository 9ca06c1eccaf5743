! The free procedures of module creepwork: versions, status messages, the
! struct initialisers, Kalker's coefficients and flexibilities, Hertz,
! Kalker's normalised FASTSIM, Polach's friction law and the wear-profile
! update.
module creepwork_functions
   use, intrinsic :: iso_c_binding, only: c_int, c_size_t, c_double, c_char, c_null_char
   use creepwork_types
   use creepwork_capi
   use creepwork_handle, only: outcome, make_outcome, buffer_outcome, set_errmsg, deliver, &
                               c_text, integer_text, message_capacity
   implicit none
   private
   public :: cw_library_version_number, cw_library_abi_version, cw_version_string
   public :: cw_status_string
   public :: cw_grid_init, cw_params_init, cw_result_init, cw_accumulation_init
   public :: cw_wear_params_init, cw_wear_result_init, cw_wear_profile_totals_init
   public :: cw_kalker_coefficients, cw_kalker_flexibilities, cw_hertz_solve
   public :: cw_fastsim_normalised, cw_wear_profile_update, cw_friction_polach

contains

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
      call c_text(capi_version_string(), s)
   end function cw_version_string

   ! Static message of a status code ("unknown status code" if not a CW_*).
   function cw_status_string(status) result(s)
      integer, intent(in) :: status
      character(len=:), allocatable :: s
      call c_text(capi_status_string(int(status, c_int)), s)
   end function cw_status_string

   ! ===================================================== struct defaults
   ! The C _init functions fail only on a NULL pointer, which a Fortran
   ! variable never is: their status is not returned.

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

   ! ======================================== linear theory, Hertz, FASTSIM
   ! Each C function writes its message into buffer: the outcome carries it.

   ! Kalker's coefficients C11, C22, C23, C33 (Kalker 1990, Table E.3).
   subroutine cw_kalker_coefficients(a_over_b, nu, coefficients, stat, errmsg)
      real(c_double), intent(in) :: a_over_b, nu
      real(c_double), intent(inout) :: coefficients(4)
      integer, intent(out), optional :: stat
      character(len=:), allocatable, intent(out), optional :: errmsg
      character(kind=c_char) :: buffer(message_capacity)
      type(outcome) :: o
      buffer(1) = c_null_char
      o = buffer_outcome(capi_kalker_coefficients(a_over_b, nu, coefficients, buffer, &
                                                size(buffer, kind=c_size_t)), buffer)
      if (present(errmsg)) call set_errmsg(o, errmsg)
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
      o = buffer_outcome(capi_kalker_flexibilities(a, b, G, nu, flexibilities, buffer, &
                                                 size(buffer, kind=c_size_t)), buffer)
      if (present(errmsg)) call set_errmsg(o, errmsg)
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
      o = buffer_outcome(capi_hertz_solve(A, B, normal_force, E_star, hertz, buffer, &
                                        size(buffer, kind=c_size_t)), buffer)
      if (present(errmsg)) call set_errmsg(o, errmsg)
      call deliver(o, stat)
   end subroutine cw_hertz_solve

   ! Polach's friction law mu0 [(1 - A) exp(-B s) + A] (B [s/m]) written into
   ! params as the exponential law: mu = A mu0, mu_e1 = (1 - A) mu0,
   ! s_h1 = ln2 / B (see the header).
   subroutine cw_friction_polach(mu0, A, B, params, stat, errmsg)
      real(c_double), intent(in) :: mu0, A, B
      type(cw_params), intent(inout), target :: params
      integer, intent(out), optional :: stat
      character(len=:), allocatable, intent(out), optional :: errmsg
      character(kind=c_char) :: buffer(message_capacity)
      type(outcome) :: o
      buffer(1) = c_null_char
      o = buffer_outcome(capi_friction_polach(mu0, A, B, params, buffer, &
                                            size(buffer, kind=c_size_t)), buffer)
      if (present(errmsg)) call set_errmsg(o, errmsg)
      call deliver(o, stat)
   end subroutine cw_friction_polach

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
      o = buffer_outcome(capi_fastsim_normalised(ux, uy, fx, fy, int(mx, c_int), int(my, c_int), &
                                               tol, tx, ty, buffer, size(buffer, kind=c_size_t)), buffer)
      if (present(errmsg)) call set_errmsg(o, errmsg)
      call deliver(o, stat)
   end subroutine cw_fastsim_normalised

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
                          trim(integer_text(size(s)))//', '// &
                          trim(integer_text(size(old_profile)))//', '// &
                          trim(integer_text(size(depth)))//': they must be equal')
      else
         buffer(1) = c_null_char
         o = buffer_outcome(capi_wear_profile_update(s, old_profile, depth, size(s, kind=c_size_t), &
                                                   smoothing, new_profile, &
                                                   size(new_profile, kind=c_size_t), buffer, &
                                                   size(buffer, kind=c_size_t)), &
                          buffer)
      end if
      if (present(errmsg)) call set_errmsg(o, errmsg)
      call deliver(o, stat)
   end subroutine cw_wear_profile_update

end module creepwork_functions
