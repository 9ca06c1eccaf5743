C     CWSOLX, the legacy entry with a model switch, as a FORTRAN 77
C     user meets it: fixed form, IMPLICIT DOUBLE PRECISION, INCLUDE
C     'creepwork_legacy.inc'. The benchmark contact (A 7.17 mm, B 5.42 mm,
C     FN 100 kN, FMU 0.3, G 82 GPa, PNU 0.28; XI 6e-4, ETA 3e-4,
C     PHI 0.2/m, partial slip) on CONTACT's layout with 16 elements
C     across the ellipse (NX = NY = 20, BOX = 20/16). Checks, for the
C     exact model (MODEL = 1) and FASTSIM (MODEL = 0) on that grid:
C      - WMAC = -(FX XI + FY ETA + FMZ PHI) (paper eq. 34), to 1e-12;
C      - the energy-consistent map sums to WMAC, is >= 0 and zero in
C        adhesion (doc/theory/work.md, doc/theory/exact.md), to 1e-12;
C      - exact: the discrete normal problem carries the load exactly,
C        dx dy sum(PZ) = FN (doc/theory/exact.md), PMAX = max(PZ),
C        PMAX within 1 % of Hertz's 3 FN/(2 pi A B) (CONTACT: 1226.8
C        of 1229.3 N/mm^2 at 20 across), WPAP = 0 in adhesion
C        and CK = WMAC/sum(WPAP); adhesion at the leading edge, slip at
C        the trailing edge of the middle strip;
C      - errors: an unknown MODEL gives IERR = 10, BOX = 0.5 IERR = 3,
C        NX = 300 with the exact model IERR = 3, and the outputs are
C        left unchanged.
      PROGRAM LEGEXA
      IMPLICIT DOUBLE PRECISION (A-H, O-Z)
      INCLUDE 'creepwork_legacy.inc'
      PARAMETER (NX = 20, NY = 20)
      PARAMETER (PI = 3.14159265358979323846D0)
      DIMENSION PX(NX, NY), PY(NX, NY), PZ(NX, NY), SX(NX, NY)
      DIMENSION SY(NX, NY), ZMAP(NX, NY), WPAP(NX, NY), WCON(NX, NY)
      INTEGER ISTATE(NX, NY)
      NFAIL = 0
      A = 7.17D-3
      B = 5.42D-3
      FN = 100.0D3
      FMU = 0.3D0
      G = 82.0D9
      PNU = 0.28D0
      XI = 6.0D-4
      ETA = 3.0D-4
      PHI = 0.2D0
      BOX = 1.25D0
      DO 50 MODEL = 1, 0, -1
         IERR = -1
         CALL CWSOLX(MODEL, A, B, FN, FMU, G, PNU, XI, ETA, PHI, NX, NY,
     &        BOX, FX, FY, FMZ, WMAC, WMIC, CK, PMAX, APPR, PX, PY, PZ,
     &        SX, SY, ZMAP, WPAP, WCON, ISTATE, IERR)
         CALL CHECKI('CWSOLX', IERR, 0, NFAIL)
         CALL CHECKR('WMAC = eq. 34', WMAC, -(FX*XI + FY*ETA + FMZ*PHI),
     &        1D-12, NFAIL)
         WSUM = 0.0D0
         PSUM = 0.0D0
         DSUM = 0.0D0
         PBIG = 0.0D0
         NBAD = 0
         NSLIP = 0
         NADH = 0
         DO 20 J = 1, NY
            DO 10 I = 1, NX
               WSUM = WSUM + WCON(I, J)
               PSUM = PSUM + PZ(I, J)
               DSUM = DSUM + WPAP(I, J)
               PBIG = MAX(PBIG, PZ(I, J))
               IF (WCON(I, J) .LT. 0.0D0) NBAD = NBAD + 1
               IF (ISTATE(I, J) .EQ. 1) THEN
                  NADH = NADH + 1
                  IF (WCON(I, J) .NE. 0.0D0) NBAD = NBAD + 1
                  IF (MODEL .EQ. 1 .AND. WPAP(I, J) .NE. 0.0D0)
     &                 NBAD = NBAD + 1
               END IF
               IF (ISTATE(I, J) .EQ. 2) NSLIP = NSLIP + 1
   10       CONTINUE
   20    CONTINUE
         CALL CHECKR('sum WCON = WMAC', WSUM, WMAC, 1D-12, NFAIL)
         CALL CHECKI('WCON >= 0, zero in adhesion', NBAD, 0, NFAIL)
         IF (NSLIP .EQ. 0 .OR. NADH .EQ. 0) THEN
            WRITE (*, *) 'not partial slip: ', NSLIP, NADH
            NFAIL = NFAIL + 1
         END IF
         IF (MODEL .EQ. 1) THEN
            DX = 2.0D0*BOX*A/NX
            DY = 2.0D0*BOX*B/NY
            CALL CHECKR('dx dy sum(PZ) = FN', DX*DY*PSUM, FN, 1D-12,
     &           NFAIL)
            CALL CHECKR('PMAX = max(PZ)', PMAX, PBIG, 0.0D0, NFAIL)
            CALL CHECKR('PMAX ~ Hertz', PMAX, 1.5D0*FN/(PI*A*B), 1D-2,
     &           NFAIL)
            CALL CHECKR('CK = WMAC/sum(WPAP)', CK, WMAC/DSUM, 1D-12,
     &           NFAIL)
            IF (APPR .LE. 0.0D0) THEN
               WRITE (*, *) 'approach not positive: ', APPR
               NFAIL = NFAIL + 1
            END IF
C           Middle strip: adhesion where material enters (I = NX side,
C           rolling towards +x), slip where it leaves.
            JM = NY/2
            IL = 0
            IT = 0
            DO 30 I = 1, NX
               IF (ISTATE(I, JM) .NE. 0) THEN
                  IF (IT .EQ. 0) IT = I
                  IL = I
               END IF
   30       CONTINUE
            CALL CHECKI('trailing element slips', ISTATE(IT, JM), 2,
     &           NFAIL)
            CALL CHECKI('leading half adheres', ISTATE(IL - 2, JM), 1,
     &           NFAIL)
            FXEXA = FX
         ELSE
C           FASTSIM on the same grid: the same contact, a different
C           theory; its longitudinal force within 10 % of the exact one.
            CALL CHECKR('FASTSIM FX ~ exact FX', FX, FXEXA, 0.1D0,
     &           NFAIL)
         END IF
   50 CONTINUE
C
C     Errors: IERR names the problem, the outputs stay as they were.
      FX = 123.0D0
      PMAX = 456.0D0
      CALL CWSOLX(7, A, B, FN, FMU, G, PNU, XI, ETA, PHI, NX, NY, BOX,
     &     FX, FY, FMZ, WMAC, WMIC, CK, PMAX, APPR, PX, PY, PZ, SX, SY,
     &     ZMAP, WPAP, WCON, ISTATE, IERR)
      CALL CHECKI('unknown MODEL', IERR, 10, NFAIL)
      CALL CWSOLX(1, A, B, FN, FMU, G, PNU, XI, ETA, PHI, NX, NY,
     &     0.5D0, FX, FY, FMZ, WMAC, WMIC, CK, PMAX, APPR, PX, PY, PZ,
     &     SX, SY, ZMAP, WPAP, WCON, ISTATE, IERR)
      CALL CHECKI('BOX 0.5', IERR, 3, NFAIL)
      CALL CWSOLX(1, A, B, FN, FMU, G, PNU, XI, ETA, PHI, 300, 1,
     &     BOX, FX, FY, FMZ, WMAC, WMIC, CK, PMAX, APPR, PX, PY, PZ,
     &     SX, SY, ZMAP, WPAP, WCON, ISTATE, IERR)
      CALL CHECKI('exact NX 300', IERR, 3, NFAIL)
      CALL CHECKR('FX unchanged', FX, 123.0D0, 0.0D0, NFAIL)
      CALL CHECKR('PMAX unchanged', PMAX, 456.0D0, 0.0D0, NFAIL)
      IF (NFAIL .EQ. 0) THEN
         WRITE (*, *) 'test_fortran_legacy_exact: all checks passed'
      ELSE
         WRITE (*, *) 'test_fortran_legacy_exact:', NFAIL, ' FAILED'
         STOP 1
      END IF
      END

      SUBROUTINE CHECKI(NAME, IVAL, IWANT, NFAIL)
      CHARACTER*(*) NAME
      INTEGER IVAL, IWANT, NFAIL
      IF (IVAL .NE. IWANT) THEN
         WRITE (*, *) NAME, ': ', IVAL, ', expected', IWANT
         NFAIL = NFAIL + 1
      END IF
      END

      SUBROUTINE CHECKR(NAME, VAL, WANT, RTOL, NFAIL)
      CHARACTER*(*) NAME
      DOUBLE PRECISION VAL, WANT, RTOL
      INTEGER NFAIL
      IF (.NOT. (ABS(VAL - WANT) .LE. RTOL*ABS(WANT))) THEN
         WRITE (*, *) NAME, ' =', VAL, ', expected', WANT
         NFAIL = NFAIL + 1
      END IF
      END
