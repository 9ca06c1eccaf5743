! cw_solver_type: owns one cw_solver -- create once, solve many times,
! destroy. Fields come back in the caller's arrays, in place.
module creepwork_solver
   use, intrinsic :: iso_c_binding, only: c_int, c_size_t, c_double, c_char, c_ptr, c_null_ptr, &
                                          c_null_char, c_loc
   use creepwork_types
   use creepwork_capi
   use creepwork_handle
   implicit none
   private

   type, public, extends(cw_handle) :: cw_solver_type
   contains
      procedure :: create => solver_create
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
      procedure :: get_patches => solver_get_patches
      procedure, nopass :: noun => solver_noun
   end type cw_solver_type

contains

   function solver_noun() result(s)
      character(len=noun_length) :: s
      s = 'solver'
   end function solver_noun

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
      character(kind=c_char) :: buffer(message_capacity)
      type(c_ptr) :: handle
      integer(c_int) :: status, gnx, gny
      type(outcome) :: o
      call self%destroy()
      buffer(1) = c_null_char
      status = capi_solver_create(make_grid(grid, nx, ny, kind, box_scale), handle, buffer, &
                                  size(buffer, kind=c_size_t))
      if (status == CW_OK) then
         status = capi_solver_grid_size(handle, gnx, gny)
         call adopt(self, handle, capi_solver_destroy, capi_solver_last_error, int(gnx), int(gny))
      end if
      o = buffer_outcome(status, buffer)
      if (present(errmsg)) call set_errmsg(o, errmsg)
      call deliver(o, stat)
   end subroutine solver_create

   ! Grid dimensions (0, 0 before create).
   subroutine solver_grid_size(self, nx, ny)
      class(cw_solver_type), intent(in) :: self
      integer, intent(out) :: nx, ny
      call grid_of(self, nx, ny)
   end subroutine solver_grid_size

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
      o = created(self)
      if (o%status == CW_OK) o = status_outcome(self, capi_solver_prepare(handle_of(self), &
                                                                          int(model, c_int)))
      if (present(errmsg)) call set_errmsg(o, errmsg)
      call deliver(o, stat)
   end subroutine solver_prepare

   ! A C pointer to the optional result (initialised when its struct_size is
   ! 0), or NULL when it is absent.
   function result_pointer(result) result(p)
      type(cw_result), intent(inout), optional, target :: result
      type(c_ptr) :: p
      integer(c_int) :: status
      p = c_null_ptr
      if (present(result)) then
         if (result%struct_size == 0) status = capi_result_init(result)
         p = c_loc(result)
      end if
   end function result_pointer

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
      type(outcome) :: o
      o = created(self)
      if (o%status == CW_OK) o = status_outcome(self, capi_solver_solve( &
                                 handle_of(self), params, int_or(mode, CW_SOLVE_FULL), &
                                 result_pointer(result)))
      if (present(errmsg)) call set_errmsg(o, errmsg)
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
      type(outcome) :: o
      real(c_double) :: row_major(4, 4)
      o = created(self)
      if (o%status == CW_OK) o = status_outcome(self, capi_solver_solve_jacobian( &
                                 handle_of(self), params, int_or(mode, CW_SOLVE_FORCES), &
                                 result_pointer(result), row_major, int(CW_JACOBIAN_LEN, c_size_t)))
      if (o%status == CW_OK) jacobian = transpose(row_major)
      if (present(errmsg)) call set_errmsg(o, errmsg)
      call deliver(o, stat)
   end subroutine solver_solve_jacobian

   ! Totals of the last successful solve.
   subroutine solver_get_result(self, result, stat, errmsg)
      class(cw_solver_type), intent(in) :: self
      type(cw_result), intent(inout) :: result
      integer, intent(out), optional :: stat
      character(len=:), allocatable, intent(out), optional :: errmsg
      type(outcome) :: o
      integer(c_int) :: status
      o = created(self)
      if (o%status == CW_OK) then
         if (result%struct_size == 0) status = capi_result_init(result)
         o = status_outcome(self, capi_solver_get_result(handle_of(self), result))
      end if
      if (present(errmsg)) call set_errmsg(o, errmsg)
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
      o = created_map(self, shape(out))
      if (o%status == CW_OK) o = status_outcome(self, capi_solver_get_field( &
                                 handle_of(self), int(field, c_int), out, size(out, kind=c_size_t)))
      if (present(errmsg)) call set_errmsg(o, errmsg)
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
      o = created(self)
      if (o%status == CW_OK) o = status_outcome(self, capi_solver_get_field( &
                                 handle_of(self), int(field, c_int), out, size(out, kind=c_size_t)))
      if (present(errmsg)) call set_errmsg(o, errmsg)
      call deliver(o, stat)
   end subroutine solver_get_field_1d

   ! Element states (CW_STATE_*) into out(nx, ny).
   subroutine solver_get_state_2d(self, out, stat, errmsg)
      class(cw_solver_type), intent(in) :: self
      integer(c_int), intent(inout), contiguous :: out(:, :)
      integer, intent(out), optional :: stat
      character(len=:), allocatable, intent(out), optional :: errmsg
      type(outcome) :: o
      o = created_map(self, shape(out))
      if (o%status == CW_OK) o = status_outcome(self, capi_solver_get_state( &
                                 handle_of(self), out, size(out, kind=c_size_t)))
      if (present(errmsg)) call set_errmsg(o, errmsg)
      call deliver(o, stat)
   end subroutine solver_get_state_2d

   subroutine solver_get_state_1d(self, out, stat, errmsg)
      class(cw_solver_type), intent(in) :: self
      integer(c_int), intent(inout), contiguous :: out(:)
      integer, intent(out), optional :: stat
      character(len=:), allocatable, intent(out), optional :: errmsg
      type(outcome) :: o
      o = created(self)
      if (o%status == CW_OK) o = status_outcome(self, capi_solver_get_state( &
                                 handle_of(self), out, size(out, kind=c_size_t)))
      if (present(errmsg)) call set_errmsg(o, errmsg)
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
      type(outcome) :: o
      type(c_ptr) :: py, pw, pp
      integer :: nx, ny
      integer(c_size_t) :: n
      call grid_of(self, nx, ny)
      n = int(ny, c_size_t)
      py = c_null_ptr
      pw = c_null_ptr
      pp = c_null_ptr
      if (present(y)) call point_at(y, py, n)
      if (present(w)) call point_at(w, pw, n)
      if (present(parabola)) call point_at(parabola, pp, n)
      o = created(self)
      if (o%status == CW_OK) o = status_outcome(self, capi_solver_get_profile(handle_of(self), &
                                                                              py, pw, pp, n))
      if (present(errmsg)) call set_errmsg(o, errmsg)
      call deliver(o, stat)
   end subroutine solver_get_profile

   ! The separate contact patches of the last solve (cw_solver_get_patches):
   ! count receives their number, patches(k), k <= count, their totals
   ! (initialised here). Without patches, or with fewer than count of them
   ! (CW_ERR_BUFFER_TOO_SMALL), only count is set.
   subroutine solver_get_patches(self, count, patches, stat, errmsg)
      class(cw_solver_type), intent(in) :: self
      integer, intent(out) :: count
      type(cw_patch), intent(inout), optional :: patches(:)
      integer, intent(out), optional :: stat
      character(len=:), allocatable, intent(out), optional :: errmsg
      type(outcome) :: o
      type(cw_patch) :: none(1)
      integer(c_size_t) :: n
      integer(c_int) :: status
      integer :: k
      count = 0
      n = 0
      o = created(self)
      if (o%status == CW_OK) then
         ! An empty or absent array asks for the count (len 0).
         status = capi_patch_init(none(1))
         if (present(patches)) then
            do k = 1, size(patches)
               status = capi_patch_init(patches(k))
            end do
         end if
         if (present(patches) .and. size(patches) > 0) then
            o = status_outcome(self, capi_solver_get_patches(handle_of(self), patches, &
                                                             int(size(patches), c_size_t), n))
         else
            o = status_outcome(self, capi_solver_get_patches(handle_of(self), none, 0_c_size_t, n))
         end if
         count = int(n)
      end if
      if (present(errmsg)) call set_errmsg(o, errmsg)
      call deliver(o, stat)
   end subroutine solver_get_patches

end module creepwork_solver
