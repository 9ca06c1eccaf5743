! creepwork_legacy_friction.f90 -- the legacy layer's friction laws of the
! slip speed, friction memory and the interface layer (doc/theory/friction.md,
! doc/theory/interface-layer.md; conventions: creepwork_legacy.f90).

! What CWFLAW and CWFMEM share: the law's cw_params and the forces-only solve
! on CWSOLX's grid.
module creepwork_legacy_law
   use, intrinsic :: iso_c_binding, only: c_double, c_int
   use creepwork, only: cw_params, cw_result, cw_solver_type, CW_GRID_UNIFORM, CW_SOLVE_FORCES, &
                        CW_OK
   use creepwork_legacy_support, only: material_params, remember
   implicit none
   private
   public :: law_params, law_forces

contains

   function law_params(MODEL, A, B, FN, FMU, G, PNU, XI, ETA, PHI, LAW, FE1, SH1, FE2, SH2, V) &
      result(p)
      integer(c_int), intent(in) :: MODEL, LAW
      real(c_double), intent(in) :: A, B, FN, FMU, G, PNU, XI, ETA, PHI, FE1, SH1, FE2, SH2, V
      type(cw_params) :: p
      p = material_params(A, B, FN, FMU, G, PNU, XI, ETA, PHI)
      p%model = MODEL
      p%friction_law = LAW
      p%mu_e1 = FE1
      p%s_h1 = SH1
      p%mu_e2 = FE2
      p%s_h2 = SH2
      p%V = V
   end function law_params

   ! Solves p on CWSOLX's grid, forces only, with its own solver; the
   ! outputs are set only on success.
   subroutine law_forces(p, NX, NY, BOX, FX, FY, FMZ, FMUR, IERR)
      type(cw_params), intent(in) :: p
      integer(c_int), intent(in) :: NX, NY
      real(c_double), intent(in) :: BOX
      real(c_double), intent(inout) :: FX, FY, FMZ
      real(c_double), intent(inout), dimension(3) :: FMUR
      integer(c_int), intent(out) :: IERR
      type(cw_result) :: r
      type(cw_solver_type) :: solver
      character(len=:), allocatable :: message
      integer :: stat
      call solver%create(nx=NX, ny=NY, kind=int(CW_GRID_UNIFORM), box_scale=BOX, stat=stat, &
                         errmsg=message)
      if (stat == CW_OK) call solver%solve(p, CW_SOLVE_FORCES, r, stat=stat, errmsg=message)
      if (stat == CW_OK) then
         FX = r%Fx
         FY = r%Fy
         FMZ = r%Mz
         FMUR = [r%mu_static, r%mu_min, r%mu_max]
      end if
      IERR = int(stat, c_int)
      call remember(message)
      call solver%destroy()
   end subroutine law_forces

end module creepwork_legacy_law

! Forces of one contact under a friction law of the slip speed, on CONTACT's
! uniform grid as CWSOLX (rolling towards +x, flexibilities or half-space
! from G and PNU), forces only:
!   MODEL     0 FASTSIM with the law at each element's own slip speed
!             (CW_MODEL_FASTSIM), 1 Kalker's exact theory (CW_MODEL_EXACT)
!   A, B, FN, G, PNU, XI, ETA, PHI, NX, NY, BOX   as CWSOLX
!   FMU       the law's kinetic coefficient mu_kin [-]
!   LAW       CONTACT's L: 0 Coulomb (FMU at every speed), 2 linear,
!             3 rational, 4 exponential (CW_FRICTION_*)
!   FE1, SH1  first falling term [-] >= 0 and its half speed [m/s]
!   FE2, SH2  second falling term and its half speed (0, 0: absent)
!   V         rolling speed [m/s] > 0 with a law: an element's slip speed is
!             its micro-slip times V
!   FX, FY    (out) creep forces on the wheel [N]
!   FMZ       (out) spin moment [N m]
!   FMUR      (out) the coefficient at rest (FMU + FE1 + FE2), and the
!             smallest and largest coefficient over the slipping elements (3)
!   IERR      0 or a CW_* status (outputs unchanged)
! Polach's law mu0 ((1 - A) exp(-B s) + A) is LAW 4 with FMU = A mu0,
! FE1 = (1 - A) mu0, SH1 = ln2 / B. Each call makes and frees its own solver.
subroutine CWFLAW(MODEL, A, B, FN, FMU, G, PNU, XI, ETA, PHI, NX, NY, BOX, LAW, FE1, SH1, FE2, &
                  SH2, V, FX, FY, FMZ, FMUR, IERR)
   use, intrinsic :: iso_c_binding, only: c_double, c_int
   use creepwork, only: CW_OK
   use creepwork_legacy_support, only: check_normal, check_cells
   use creepwork_legacy_law, only: law_params, law_forces
   implicit none
   integer(c_int), intent(in) :: MODEL, NX, NY, LAW
   real(c_double), intent(in) :: A, B, FN, FMU, G, PNU, XI, ETA, PHI, BOX, FE1, SH1, FE2, SH2, V
   real(c_double), intent(inout) :: FX, FY, FMZ
   real(c_double), intent(inout), dimension(3) :: FMUR
   integer(c_int), intent(out) :: IERR
   call check_cells(NX, 'NX', IERR)
   if (IERR == CW_OK) call check_cells(NY, 'NY', IERR)
   if (IERR == CW_OK) call check_normal([A, B, FN, FMU, G, PNU, XI, ETA, PHI, BOX, FE1, SH1, FE2, &
                                         SH2, V], 'A B FN FMU G PNU XI ETA PHI BOX FE1 SH1 FE2 SH2 V', &
                                        IERR)
   if (IERR /= CW_OK) return
   call law_forces(law_params(MODEL, A, B, FN, FMU, G, PNU, XI, ETA, PHI, LAW, FE1, SH1, FE2, SH2, &
                              V), NX, NY, BOX, FX, FY, FMZ, FMUR, IERR)
end subroutine CWFLAW

! CWFLAW with friction memory and an interface layer (cw_params'
! memory_distance, memory_s0, layer_h, layer_G, tau_c0, k_tau; the
! library's messages name them so):
!   MODEL ... V   as CWFLAW
!   DC        memory: the characteristic slip distance d_c [m] >= 0 (0: none;
!             it acts with a law, LAW > 0)
!   S0        memory: the background slip speed s0 [m/s] >= 0
!   HL, G3    the layer's thickness [m] >= 0 (0: none) and shear modulus
!             [Pa], > 0 when HL > 0: the exact model (MODEL 1) only
!   TAUC0     the layer's yield stress [Pa] >= 0 (0: none): the exact model
!             with Coulomb's law (LAW 0)
!   TAUK      its hardening with the plastic displacement [Pa/m] (0)
!   FX, FY, FMZ, FMUR, IERR   as CWFLAW
subroutine CWFMEM(MODEL, A, B, FN, FMU, G, PNU, XI, ETA, PHI, NX, NY, BOX, LAW, FE1, SH1, FE2, &
                  SH2, V, DC, S0, HL, G3, TAUC0, TAUK, FX, FY, FMZ, FMUR, IERR)
   use, intrinsic :: iso_c_binding, only: c_double, c_int
   use creepwork, only: cw_params, CW_OK
   use creepwork_legacy_support, only: check_normal, check_cells
   use creepwork_legacy_law, only: law_params, law_forces
   implicit none
   integer(c_int), intent(in) :: MODEL, NX, NY, LAW
   real(c_double), intent(in) :: A, B, FN, FMU, G, PNU, XI, ETA, PHI, BOX, FE1, SH1, FE2, SH2, V
   real(c_double), intent(in) :: DC, S0, HL, G3, TAUC0, TAUK
   real(c_double), intent(inout) :: FX, FY, FMZ
   real(c_double), intent(inout), dimension(3) :: FMUR
   integer(c_int), intent(out) :: IERR
   type(cw_params) :: p
   call check_cells(NX, 'NX', IERR)
   if (IERR == CW_OK) call check_cells(NY, 'NY', IERR)
   if (IERR == CW_OK) call check_normal([A, B, FN, FMU, G, PNU, XI, ETA, PHI, BOX, FE1, SH1, FE2, &
                                         SH2, V, DC, S0, HL, G3, TAUC0, TAUK], &
                                        'A B FN FMU G PNU XI ETA PHI BOX FE1 SH1 FE2 SH2 V DC S0 HL '// &
                                        'G3 TAUC0 TAUK', IERR)
   if (IERR /= CW_OK) return
   p = law_params(MODEL, A, B, FN, FMU, G, PNU, XI, ETA, PHI, LAW, FE1, SH1, FE2, SH2, V)
   p%memory_distance = DC
   p%memory_s0 = S0
   p%layer_h = HL
   p%layer_G = G3
   p%tau_c0 = TAUC0
   p%k_tau = TAUK
   call law_forces(p, NX, NY, BOX, FX, FY, FMZ, FMUR, IERR)
end subroutine CWFMEM
