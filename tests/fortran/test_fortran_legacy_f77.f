C     The legacy layer as a FORTRAN 77 user meets it: fixed form,
C     IMPLICIT DOUBLE PRECISION, INCLUDE 'creepwork_legacy.inc' from the
C     installed include directory, every routine called. Checks:
C      - CWTYPE accepts REAL*8 and INTEGER*4 (this program's kinds);
C      - CWERRM gives the header's message for IERR = 2;
C      - CWKALK: Kalker 1990 Table E.3 at a/b = 1, nu = 0.25
C        (C11 4.12, C22 3.67, C23 1.47, C33 1.19 as printed there,
C        tests/data/kalker_cij.csv);
C      - CWFLEX: L1 = 8A/(3 C11 G) etc. from those coefficients;
C      - CWHERT: doc/validation/index.md (R 457 mm wheel on a 300 mm crown,
C        100 kN, G 82 GPa, nu 0.28): A = 7.169984332 mm, B = 5.416941278
C        mm, P0 = 1229.3316 MPa, approach 0.10515124 mm;
C      - CWSOLL with CWFLEX's L's = CWSOLM bit for bit;
C      - CWFSIM with UX = pi A^2 B XI/(2 FMU FN FL1) etc. (no spin, even
C        NY: Kalker's strips are CWSOLM's) = CWSOLM's forces / (FMU FN);
C      - CWACCU: the accumulated energy-consistent map sums to WMSUM;
C      - a subnormal input (a REAL passed for DOUBLE PRECISION, high word
C        zero) gives IERR = 2.
      PROGRAM LEGF77
      IMPLICIT DOUBLE PRECISION (A-H, O-Z)
      INCLUDE 'creepwork_legacy.inc'
      PARAMETER (NX = 16, NY = 12)
      PARAMETER (PI = 3.14159265358979323846D0)
      DIMENSION PX(NX, NY), PY(NX, NY), SX(NX, NY), SY(NX, NY)
      DIMENSION ZMAP(NX, NY), WPAP(NX, NY), WCON(NX, NY)
      DIMENSION PX2(NX, NY), PY2(NX, NY), SX2(NX, NY), SY2(NX, NY)
      DIMENSION ZMAP2(NX, NY), WPAP2(NX, NY), WCON2(NX, NY)
      DIMENSION WPACC(NX, NY), WCACC(NX, NY)
      DIMENSION R(2)
      INTEGER ISTATE(NX, NY), ISTAT2(NX, NY), N(2)
      CHARACTER*80 MSG
      NFAIL = 0
C
      R(1) = 1.0D0
      R(2) = 2.0D0
      N(1) = 1
      N(2) = 2
      IERR = -1
      CALL CWTYPE(R, N, IERR)
      CALL CHECKI('CWTYPE', IERR, 0, NFAIL)
      CALL CWERRM(2, MSG)
      IF (MSG .NE. 'an input value is invalid (NaN, Inf, out of range)')
     &   THEN
         WRITE (*, *) 'CWERRM(2): ', MSG
         NFAIL = NFAIL + 1
      END IF
C
      CALL CWKALK(1.0D0, 0.25D0, C11, C22, C23, C33, IERR)
      CALL CHECKI('CWKALK', IERR, 0, NFAIL)
      CALL CHECKR('C11', C11, 4.12D0, 1D-12, NFAIL)
      CALL CHECKR('C22', C22, 3.67D0, 1D-12, NFAIL)
      CALL CHECKR('C23', C23, 1.47D0, 1D-12, NFAIL)
      CALL CHECKR('C33', C33, 1.19D0, 1D-12, NFAIL)
C
      A = 6.0D-3
      B = 4.5D-3
      G = 82.0D9
      PNU = 0.28D0
      CALL CWKALK(A/B, PNU, C11, C22, C23, C33, IERR)
      CALL CWFLEX(A, B, G, PNU, FL1, FL2, FL3, IERR)
      CALL CHECKI('CWFLEX', IERR, 0, NFAIL)
      CALL CHECKR('L1', FL1, 8*A/(3*C11*G), 1D-14, NFAIL)
      CALL CHECKR('L2', FL2, 8*A/(3*C22*G), 1D-14, NFAIL)
      CALL CHECKR('L3', FL3, PI*A*SQRT(A/B)/(4*C23*G), 1D-14, NFAIL)
C
      CALL CWHERT(1/(2*0.457D0), 1/(2*0.300D0), 100.0D3,
     &            82.0D9/(1 - 0.28D0), HA, HB, P0, APPR, IERR)
      CALL CHECKI('CWHERT', IERR, 0, NFAIL)
      CALL CHECKR('Hertz a', HA, 7.169984332D-3, 1D-9, NFAIL)
      CALL CHECKR('Hertz b', HB, 5.416941278D-3, 1D-9, NFAIL)
      CALL CHECKR('Hertz p0', P0, 1229.3316D6, 1D-7, NFAIL)
      CALL CHECKR('Hertz approach', APPR, 0.10515124D-3, 1D-7, NFAIL)
C
      FN = 80.0D3
      FMU = 0.3D0
      XI = 6.0D-4
      ETA = -3.0D-4
      PHI = 0.0D0
      CALL CWSOLM(A, B, FN, FMU, G, PNU, XI, ETA, PHI, NX, NY,
     &            FX, FY, FMZ, WMAC, WMIC, CK, PX, PY, SX, SY,
     &            ZMAP, WPAP, WCON, ISTATE, IERR)
      CALL CHECKI('CWSOLM', IERR, 0, NFAIL)
      CALL CWSOLL(A, B, FN, FMU, FL1, FL2, FL3, XI, ETA, PHI, NX, NY,
     &            FX2, FY2, FMZ2, WMAC2, WMIC2, CK2, PX2, PY2, SX2, SY2,
     &            ZMAP2, WPAP2, WCON2, ISTAT2, IERR)
      CALL CHECKI('CWSOLL', IERR, 0, NFAIL)
      CALL CHECKR('CWSOLL FX', FX2, FX, 0D0, NFAIL)
      CALL CHECKR('CWSOLL FY', FY2, FY, 0D0, NFAIL)
      CALL CHECKR('CWSOLL WMAC', WMAC2, WMAC, 0D0, NFAIL)
C
      SCALE = PI*A*A*B/(2*FMU*FN)
      CALL CWFSIM(SCALE*XI/FL1, SCALE*ETA/FL2, 0.0D0, 0.0D0, NX, NY,
     &            1.0D0, TX, TY, IERR)
      CALL CHECKI('CWFSIM', IERR, 0, NFAIL)
      CALL CHECKR('CWFSIM TX', TX, -FX/(FMU*FN), 1D-12, NFAIL)
      CALL CHECKR('CWFSIM TY', TY, FY/(FMU*FN), 1D-12, NFAIL)
C
      DSUM = 0.0D0
      WMSUM = 0.0D0
      WPSUM = 0.0D0
      DO 20 J = 1, NY
         DO 10 I = 1, NX
            WPACC(I, J) = 0.0D0
            WCACC(I, J) = 0.0D0
   10    CONTINUE
   20 CONTINUE
      DO 30 K = 1, 2
         CALL CWACCU(NX, NY, 0.03D0, WMAC, WMIC, WPAP, WCON, DSUM,
     &               WMSUM, WPSUM, WPACC, WCACC, CKRUN, IERR)
         CALL CHECKI('CWACCU', IERR, 0, NFAIL)
   30 CONTINUE
      S = 0.0D0
      DO 50 J = 1, NY
         DO 40 I = 1, NX
            S = S + WCACC(I, J)
   40    CONTINUE
   50 CONTINUE
      CALL CHECKR('CWACCU map sum', S, WMSUM, 1D-12, NFAIL)
      CALL CHECKR('CWACCU WMSUM', WMSUM, 0.06D0*WMAC, 1D-15, NFAIL)
C
C     A subnormal DOUBLE PRECISION is what a REAL followed by four zero
C     bytes reads as: rejected, outputs untouched.
      SUB = 1.0D-310
      FXOLD = FX
      CALL CWSOLM(A, B, FN, FMU, G, PNU, SUB, ETA, PHI, NX, NY,
     &            FX, FY, FMZ, WMAC, WMIC, CK, PX, PY, SX, SY,
     &            ZMAP, WPAP, WCON, ISTATE, IERR)
      CALL CHECKI('CWSOLM subnormal', IERR, 2, NFAIL)
      CALL CHECKR('CWSOLM untouched', FX, FXOLD, 0D0, NFAIL)
C
      IF (NFAIL .NE. 0) THEN
         WRITE (*, *) NFAIL, ' checks failed'
         STOP 1
      END IF
      WRITE (*, '(A)') 'legacy F77 layer: all checks passed'
      END

      SUBROUTINE CHECKI(NAME, IVAL, IWANT, NFAIL)
      CHARACTER*(*) NAME
      INTEGER IVAL, IWANT, NFAIL
      IF (IVAL .NE. IWANT) THEN
         WRITE (*, *) NAME, ': IERR =', IVAL, ', expected', IWANT
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
