! creepwork_legacy_friction.f90 -- the legacy layer's friction laws of the
! slip speed (doc/theory/friction.md; conventions: creepwork_legacy.f90).

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
   use creepwork, only: cw_params, cw_result, cw_solver_type, CW_GRID_UNIFORM, CW_SOLVE_FORCES, &
                        CW_OK
   use creepwork_legacy_support, only: check_normal, check_cells, material_params, remember
   implicit none
   integer(c_int), intent(in) :: MODEL, NX, NY, LAW
   real(c_double), intent(in) :: A, B, FN, FMU, G, PNU, XI, ETA, PHI, BOX, FE1, SH1, FE2, SH2, V
   real(c_double), intent(inout) :: FX, FY, FMZ
   real(c_double), intent(inout), dimension(3) :: FMUR
   integer(c_int), intent(out) :: IERR
   type(cw_params) :: p
   type(cw_result) :: r
   type(cw_solver_type) :: solver
   character(len=:), allocatable :: message
   integer :: stat
   call check_cells(NX, 'NX', IERR)
   if (IERR == CW_OK) call check_cells(NY, 'NY', IERR)
   if (IERR == CW_OK) call check_normal([A, B, FN, FMU, G, PNU, XI, ETA, PHI, BOX, FE1, SH1, FE2, &
                                         SH2, V], 'A B FN FMU G PNU XI ETA PHI BOX FE1 SH1 FE2 SH2 V', &
                                        IERR)
   if (IERR /= CW_OK) return
   p = material_params(A, B, FN, FMU, G, PNU, XI, ETA, PHI)
   p%model = MODEL
   p%friction_law = LAW
   p%mu_e1 = FE1
   p%s_h1 = SH1
   p%mu_e2 = FE2
   p%s_h2 = SH2
   p%V = V
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
end subroutine CWFLAW
