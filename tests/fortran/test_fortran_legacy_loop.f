C     A legacy time loop, FORTRAN 77 as the old vehicle codes are written:
C     no module, DOUBLE PRECISION, CALL CWSOLM + CALL CWACCU every step.
C     10,000 steps of varying creepage (longitudinal, lateral and spin
C     with incommensurate periods, partial to full slip), V*dt = 1 cm.
C     Asserts (paper eqs. 34-39; creepwork.h "Work"):
C       - every step: IERR = 0 and the energy-consistent map sums to that
C         step's macro work W_macro (1e-10 relative);
C       - the accumulated macro total equals the sum of the per-step
C         totals W_macro*V*dt (eq. 35) and the accumulated paper total
C         the sum of W_micro*V*dt (eq. 37), 1e-10 relative;
C       - the accumulated energy-consistent distribution sums to the
C         accumulated macro total (1e-10 relative);
C       - K over the run is their ratio (eq. 39) and the distance is
C         10,000*V*dt.
      PROGRAM LLOOP
      IMPLICIT NONE
      INTEGER NX, NY, NSTEP
      PARAMETER (NX = 10, NY = 8, NSTEP = 10000)
      DOUBLE PRECISION PI
      PARAMETER (PI = 3.14159265358979323846D0)
      DOUBLE PRECISION A, B, FN, FMU, G, PNU, XI, ETA, PHI, DIST
      DOUBLE PRECISION FX, FY, FMZ, WMAC, WMIC, CK
      DOUBLE PRECISION PX(NX, NY), PY(NX, NY), SX(NX, NY), SY(NX, NY)
      DOUBLE PRECISION ZMAP(NX, NY), WPAP(NX, NY), WCON(NX, NY)
      DOUBLE PRECISION WPACC(NX, NY), WCACC(NX, NY)
      INTEGER ISTATE(NX, NY)
      DOUBLE PRECISION DSUM, WMSUM, WPSUM, CKRUN, SUMW, SUMP, T, S
      INTEGER K, I, J, IERR, NFAIL, NSLIP, NADH
      LOGICAL CLOSE
      EXTERNAL CWSOLM, CWACCU
C
      A = 6.5D-3
      B = 4.2D-3
      FN = 75.0D3
      FMU = 0.3D0
      G = 82.0D9
      PNU = 0.28D0
      DIST = 0.01D0
      DSUM = 0.0D0
      WMSUM = 0.0D0
      WPSUM = 0.0D0
      CKRUN = 0.0D0
      SUMW = 0.0D0
      SUMP = 0.0D0
      NFAIL = 0
      NSLIP = 0
      NADH = 0
      DO 20 J = 1, NY
         DO 10 I = 1, NX
            WPACC(I, J) = 0.0D0
            WCACC(I, J) = 0.0D0
   10    CONTINUE
   20 CONTINUE
C
      DO 100 K = 1, NSTEP
         T = DBLE(K)
         XI = 2.0D-3*SIN(2.0D0*PI*T/997.0D0)
         ETA = 1.5D-3*COS(2.0D0*PI*T/613.0D0)
         PHI = 1.2D0*SIN(2.0D0*PI*T/1531.0D0)
         CALL CWSOLM(A, B, FN, FMU, G, PNU, XI, ETA, PHI, NX, NY,
     &               FX, FY, FMZ, WMAC, WMIC, CK, PX, PY, SX, SY,
     &               ZMAP, WPAP, WCON, ISTATE, IERR)
         IF (IERR .NE. 0) THEN
            WRITE (*, *) 'FAIL CWSOLM IERR =', IERR, ' at step', K
            NFAIL = NFAIL + 1
            GO TO 100
         END IF
         S = 0.0D0
         DO 40 J = 1, NY
            DO 30 I = 1, NX
               S = S + WCON(I, J)
               IF (ISTATE(I, J) .EQ. 2) NSLIP = NSLIP + 1
               IF (ISTATE(I, J) .EQ. 1) NADH = NADH + 1
   30       CONTINUE
   40    CONTINUE
         IF (.NOT. CLOSE(S, WMAC, 1.0D-10)) THEN
            WRITE (*, *) 'FAIL step', K, ': sum WCON =', S,
     &                   ' W_macro =', WMAC
            NFAIL = NFAIL + 1
         END IF
         SUMW = SUMW + WMAC*DIST
         SUMP = SUMP + WMIC*DIST
         CALL CWACCU(NX, NY, DIST, WMAC, WMIC, WPAP, WCON, DSUM, WMSUM,
     &               WPSUM, WPACC, WCACC, CKRUN, IERR)
         IF (IERR .NE. 0) THEN
            WRITE (*, *) 'FAIL CWACCU IERR =', IERR, ' at step', K
            NFAIL = NFAIL + 1
         END IF
  100 CONTINUE
C
      S = 0.0D0
      DO 120 J = 1, NY
         DO 110 I = 1, NX
            S = S + WCACC(I, J)
  110    CONTINUE
  120 CONTINUE
      IF (.NOT. CLOSE(WMSUM, SUMW, 1.0D-10)) THEN
         WRITE (*, *) 'FAIL accumulated W_macro', WMSUM, ' vs', SUMW
         NFAIL = NFAIL + 1
      END IF
      IF (.NOT. CLOSE(WPSUM, SUMP, 1.0D-10)) THEN
         WRITE (*, *) 'FAIL accumulated W_micro', WPSUM, ' vs', SUMP
         NFAIL = NFAIL + 1
      END IF
      IF (.NOT. CLOSE(S, WMSUM, 1.0D-10)) THEN
         WRITE (*, *) 'FAIL sum of accumulated map', S, ' vs', WMSUM
         NFAIL = NFAIL + 1
      END IF
      IF (.NOT. CLOSE(CKRUN, WMSUM/WPSUM, 1.0D-15)) THEN
         WRITE (*, *) 'FAIL K over the run', CKRUN, ' vs', WMSUM/WPSUM
         NFAIL = NFAIL + 1
      END IF
      IF (.NOT. CLOSE(DSUM, NSTEP*DIST, 1.0D-12)) THEN
         WRITE (*, *) 'FAIL distance', DSUM, ' vs', NSTEP*DIST
         NFAIL = NFAIL + 1
      END IF
C     The loop must have seen both slip and adhesion.
      IF (NSLIP .EQ. 0 .OR. NADH .EQ. 0) THEN
         WRITE (*, *) 'FAIL no partial slip: slip', NSLIP, ' adh', NADH
         NFAIL = NFAIL + 1
      END IF
      WRITE (*, '(A, I6, A, 1P, E23.15, A, E23.15, A, 0P, F9.6)')
     &   'steps', NSTEP, '  W_macro [J]', WMSUM, '  W_micro [J]',
     &   WPSUM, '  K', CKRUN
      IF (NFAIL .NE. 0) THEN
         WRITE (*, *) NFAIL, ' checks failed'
         STOP 1
      END IF
      WRITE (*, *) 'test_fortran_legacy_loop: all checks passed'
      END

C     |X - Y| <= RTOL*|Y|
      LOGICAL FUNCTION CLOSE(X, Y, RTOL)
      DOUBLE PRECISION X, Y, RTOL
      CLOSE = ABS(X - Y) .LE. RTOL*ABS(Y)
      END
