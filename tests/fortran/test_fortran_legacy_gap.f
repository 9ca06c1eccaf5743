C     CWSOLG, the legacy entry for a contact of any shape, as a FORTRAN
C     77 user meets it: fixed form, IMPLICIT DOUBLE PRECISION, INCLUDE
C     'creepwork_legacy.inc'. Expected values:
C      - a Hertzian gap GA X**2 + GB Y**2 (R 0.46 m on a 0.30 m crown)
C        on the uniform grid over 1.2 A x 1.2 B, A and B from Hertz's
C        theory (CWHERT), is the discrete problem that CWSOLX's exact
C        model solves on that layout (doc/theory/non-hertzian.md):
C        forces and moment within 1e-6 of MU FN (both at tolerance
C        1e-8), the same pressure peak to 1e-6;
C      - the approach found, prescribed again (LOAD = 1), gives back FN
C        to 1e-6;
C      - two lobes far apart are two patches (NPATCH = 2) for FASTSIM
C        on the semi-Hertzian normal problem;
C      - errors: LOAD = 2 gives IERR = 10 naming LOAD, NX = 2 IERR = 3,
C        and the outputs are left unchanged.
      PROGRAM LEGGAP
      IMPLICIT DOUBLE PRECISION (A-H, O-Z)
      INCLUDE 'creepwork_legacy.inc'
      PARAMETER (N = 24)
      PARAMETER (S = 1.2D0)
      DIMENSION H(N, N), PX(N, N), PY(N, N), PZ(N, N), WCON(N, N)
      DIMENSION QX(N, N), QY(N, N), QZ(N, N), SX(N, N), SY(N, N)
      DIMENSION ZMAP(N, N), WPAP(N, N), WCOX(N, N)
      INTEGER ISTATE(N, N), JSTATE(N, N)
      CHARACTER*200 MSG
      NFAIL = 0
      GA = 1.0D0/(2.0D0*0.46D0)
      GB = 1.0D0/(2.0D0*0.30D0)
      FN = 60.0D3
      FMU = 0.3D0
      G = 82.0D9
      PNU = 0.28D0
      XI = 4.0D-4
      ETA = -3.0D-4
      PHI = 0.3D0
      CALL CWHERT(GA, GB, FN, G/(1.0D0 - PNU), A, B, P0, APPR0, IERR)
      CALL CHECKI('CWHERT', IERR, 0, NFAIL)
      DX = 2.0D0*S*A/N
      DY = 2.0D0*S*B/N
      X0 = -S*A + 0.5D0*DX
      Y0 = -S*B + 0.5D0*DY
      DO 20 J = 1, N
         DO 10 I = 1, N
            X = X0 + (I - 1)*DX
            Y = Y0 + (J - 1)*DY
            H(I, J) = GA*X**2 + GB*Y**2
   10    CONTINUE
   20 CONTINUE
      F = FN
      AP = 0.0D0
      CALL CWSOLG(1, 0, N, N, X0, Y0, DX, DY, H, 0, F, AP, FMU, G, PNU,
     &     XI, ETA, PHI, FX, FY, FMZ, WMAC, PMAX, NP, PX, PY, PZ, WCON,
     &     ISTATE, IERR)
      CALL CHECKI('CWSOLG', IERR, 0, NFAIL)
      CALL CHECKI('NPATCH', NP, 1, NFAIL)
      CALL CHECKR('FN', F, FN, 1D-12, 0.0D0, NFAIL)
      CALL CWSOLX(1, A, B, FN, FMU, G, PNU, XI, ETA, PHI, N, N, S,
     &     GX, GY, GMZ, GMAC, GMIC, CK, QMAX, QAPP, QX, QY, QZ, SX, SY,
     &     ZMAP, WPAP, WCOX, JSTATE, IERR)
      CALL CHECKI('CWSOLX', IERR, 0, NFAIL)
      CALL CHECKR('FX', FX, GX, 0.0D0, 1D-6*FMU*FN, NFAIL)
      CALL CHECKR('FY', FY, GY, 0.0D0, 1D-6*FMU*FN, NFAIL)
      CALL CHECKR('FMZ', FMZ, GMZ, 0.0D0, 1D-6*FMU*FN*A, NFAIL)
      CALL CHECKR('PMAX', PMAX, QMAX, 1D-6, 0.0D0, NFAIL)
      CALL CHECKR('WMAC', WMAC, -(FX*XI + FY*ETA + FMZ*PHI), 1D-12,
     &     0.0D0, NFAIL)
C     The approach found, prescribed
      F2 = 0.0D0
      CALL CWSOLG(1, 0, N, N, X0, Y0, DX, DY, H, 1, F2, AP, FMU, G,
     &     PNU, XI, ETA, PHI, FX, FY, FMZ, WMAC, PMAX, NP, PX, PY, PZ,
     &     WCON, ISTATE, IERR)
      CALL CHECKI('CWSOLG LOAD=1', IERR, 0, NFAIL)
      CALL CHECKR('FN from APPR', F2, FN, 1D-6, 0.0D0, NFAIL)
C     Two lobes: the same bowl on either side of y = 0, far apart
C     (across rows: the semi-Hertzian method takes one locus per row)
      DO 40 J = 1, N
         DO 30 I = 1, N
            X = X0 + (I - 1)*DX
            Y = Y0 + (J - 1)*DY
            YL = ABS(Y) - 0.5D0*S*B
            H(I, J) = GA*X**2 + 16.0D0*GB*YL**2
   30    CONTINUE
   40 CONTINUE
      F = FN
      CALL CWSOLG(0, 1, N, N, X0, Y0, DX, DY, H, 0, F, AP, FMU, G, PNU,
     &     XI, ETA, PHI, FX, FY, FMZ, WMAC, PMAX, NP, PX, PY, PZ, WCON,
     &     ISTATE, IERR)
      CALL CHECKI('CWSOLG two lobes', IERR, 0, NFAIL)
      CALL CHECKI('NPATCH two lobes', NP, 2, NFAIL)
C     Errors leave the outputs alone
      FX = -1.0D0
      CALL CWSOLG(1, 0, N, N, X0, Y0, DX, DY, H, 2, F, AP, FMU, G, PNU,
     &     XI, ETA, PHI, FX, FY, FMZ, WMAC, PMAX, NP, PX, PY, PZ, WCON,
     &     ISTATE, IERR)
      CALL CHECKI('LOAD = 2', IERR, 10, NFAIL)
      CALL CWLAST(MSG)
      IF (INDEX(MSG, 'LOAD') .EQ. 0) THEN
         WRITE (*, *) 'LOAD not named: ', MSG
         NFAIL = NFAIL + 1
      END IF
      CALL CWSOLG(1, 0, 2, N, X0, Y0, DX, DY, H, 0, F, AP, FMU, G, PNU,
     &     XI, ETA, PHI, FX, FY, FMZ, WMAC, PMAX, NP, PX, PY, PZ, WCON,
     &     ISTATE, IERR)
      CALL CHECKI('NX = 2', IERR, 3, NFAIL)
      CALL CHECKR('FX unchanged', FX, -1.0D0, 0.0D0, 0.0D0, NFAIL)
      IF (NFAIL .EQ. 0) THEN
         WRITE (*, *) 'all checks passed'
      ELSE
         WRITE (*, *) NFAIL, ' checks failed'
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

C     |VAL - WANT| <= RTOL |WANT| + ATOL
      SUBROUTINE CHECKR(NAME, VAL, WANT, RTOL, ATOL, NFAIL)
      CHARACTER*(*) NAME
      DOUBLE PRECISION VAL, WANT, RTOL, ATOL
      INTEGER NFAIL
      IF (.NOT. (ABS(VAL - WANT) .LE. RTOL*ABS(WANT) + ATOL)) THEN
         WRITE (*, *) NAME, ' =', VAL, ', expected', WANT
         NFAIL = NFAIL + 1
      END IF
      END
