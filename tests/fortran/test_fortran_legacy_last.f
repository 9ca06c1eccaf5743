C     CWLAST from FORTRAN 77 (fixed form, IMPLICIT DOUBLE PRECISION,
C     the installed INCLUDE file): after a failing call it names the
C     offending input, as the C ABI and module creepwork do. Expected
C     texts are the header's message of the status (creepwork.h,
C     CW_STATUS_LIST) followed by the input's name and value:
C      - CWKALK with PNU = 0.6 (Poisson's ratio must lie in [0, 0.5]):
C        "an input value is invalid (...): nu = 0.6 ...";
C      - MSG shorter than the message gets its first LEN(MSG)
C        characters; a longer one is blank-padded;
C      - after a success the message is blank; CWERRM and CWLAST leave
C        it unchanged;
C      - CWSOLM with PNU = 0.6 names nu and its range, with NX = 0 nx;
C      - a subnormal A (a REAL passed for DOUBLE PRECISION) names A, and
C        so does a huge one (a REAL followed by other bytes): a hint;
C      - CWCHEK gives the library's plausibility findings;
C      - CWFORC with LOAD = 2 names exact_load (0 or 1), with NY = 0 ny;
C      - CWACCU with DIST = -1 names DIST.
      PROGRAM LEGLST
      IMPLICIT DOUBLE PRECISION (A-H, O-Z)
      INCLUDE 'creepwork_legacy.inc'
      PARAMETER (NX = 8, NY = 6)
      DIMENSION PX(NX, NY), PY(NX, NY), SX(NX, NY), SY(NX, NY)
      DIMENSION ZMAP(NX, NY), WPAP(NX, NY), WCON(NX, NY)
      DIMENSION WPACC(NX, NY), WCACC(NX, NY)
      INTEGER ISTATE(NX, NY)
      CHARACTER*200 MSG
      INTEGER IBITS(2)
      DOUBLE PRECISION RBITS
      EQUIVALENCE (IBITS, RBITS)
      CHARACTER*10 SHORT
      CHARACTER*52 HEAD
      PARAMETER (HEAD =
     &   'an input value is invalid (NaN, Inf, out of range): ')
      NFAIL = 0
C
      CALL CWKALK(1.0D0, 0.6D0, C11, C22, C23, C33, IERR)
      CALL CHECKI('CWKALK nu = 0.6', IERR, 2, NFAIL)
      CALL CWLAST(MSG)
      CALL HAS('CWKALK', MSG, HEAD, NFAIL)
      CALL HAS('CWKALK', MSG, 'nu = 0.6', NFAIL)
C     The message ends in blanks up to LEN(MSG).
      L = LEN_TRIM(MSG)
      IF (L .LT. 60 .OR. L .GE. LEN(MSG)) THEN
         WRITE (*, *) 'CWLAST length', L
         NFAIL = NFAIL + 1
      END IF
      CALL CWLAST(SHORT)
      IF (SHORT .NE. 'an input v') THEN
         WRITE (*, *) 'CWLAST into CHARACTER*10: [', SHORT, ']'
         NFAIL = NFAIL + 1
      END IF
C     CWERRM and CWLAST do not change the message.
      CALL CWERRM(0, MSG)
      CALL CWLAST(MSG)
      CALL HAS('after CWERRM', MSG, 'nu = 0.6', NFAIL)
C     A success clears it.
      CALL CWKALK(1.0D0, 0.25D0, C11, C22, C23, C33, IERR)
      CALL CHECKI('CWKALK nu = 0.25', IERR, 0, NFAIL)
      CALL CWLAST(MSG)
      IF (MSG .NE. ' ') THEN
         WRITE (*, *) 'CWLAST after a success: ', MSG
         NFAIL = NFAIL + 1
      END IF
C
      A = 6.0D-3
      B = 4.5D-3
      FN = 80.0D3
      FMU = 0.3D0
      G = 82.0D9
      XI = 6.0D-4
      ETA = -3.0D-4
      PHI = 0.5D0
      CALL CWSOLM(A, B, FN, FMU, G, 0.6D0, XI, ETA, PHI, NX, NY,
     &            FX, FY, FMZ, WMAC, WMIC, CK, PX, PY, SX, SY,
     &            ZMAP, WPAP, WCON, ISTATE, IERR)
      CALL CHECKI('CWSOLM nu = 0.6', IERR, 2, NFAIL)
      CALL CWLAST(MSG)
      CALL HAS('CWSOLM nu', MSG, 'nu = 0.', NFAIL)
      CALL HAS('CWSOLM nu', MSG, 'must lie in [0, 0.5]', NFAIL)
      CALL CWSOLM(A, B, FN, FMU, G, 0.28D0, XI, ETA, PHI, 0, NY,
     &            FX, FY, FMZ, WMAC, WMIC, CK, PX, PY, SX, SY,
     &            ZMAP, WPAP, WCON, ISTATE, IERR)
      CALL CHECKI('CWSOLM NX = 0', IERR, 3, NFAIL)
      CALL CWLAST(MSG)
      CALL HAS('CWSOLM nx', MSG, 'nx = 0', NFAIL)
C     1D-300 * 1D-10 is subnormal: the pattern of a REAL argument.
      TINY = 1.0D-300
      TINY = TINY * 1.0D-10
      CALL CWSOLM(TINY, B, FN, FMU, G, 0.28D0, XI, ETA, PHI, NX, NY,
     &            FX, FY, FMZ, WMAC, WMIC, CK, PX, PY, SX, SY,
     &            ZMAP, WPAP, WCON, ISTATE, IERR)
      CALL CHECKI('CWSOLM subnormal A', IERR, 2, NFAIL)
      CALL CWLAST(MSG)
      CALL HAS('CWSOLM subnormal', MSG, 'A is a subnormal', NFAIL)
C     A REAL 0.0072 followed by the four bytes of another REAL reads
C     as a huge DOUBLE PRECISION (3BEBEDFA, 47000000 high: 2**113).
      IBITS(1) = INT(Z'3BEBEDFA')
      IBITS(2) = INT(Z'47000000')
      CALL CWSOLM(RBITS, B, FN, FMU, G, 0.28D0, XI, ETA, PHI, NX, NY,
     &            FX, FY, FMZ, WMAC, WMIC, CK, PX, PY, SX, SY,
     &            ZMAP, WPAP, WCON, ISTATE, IERR)
      CALL CHECKI('CWSOLM huge A', IERR, 2, NFAIL)
      CALL CWLAST(MSG)
      CALL HAS('CWSOLM huge A', MSG, 'A = ', NFAIL)
      CALL HAS('CWSOLM huge A', MSG,
     &         'a REAL passed for DOUBLE PRECISION', NFAIL)
C     CWCHEK: the library's checks of CWSOLM's inputs. A = 7.2 m
C     (mm typed as m; the rule's bound is 0.1 m) and FMU = 5 (above
C     1.5): two findings in the rules' order; A = B = 6 mm and
C     FN = 80 kN given explicitly are no placeholders: none.
      CALL CWCHEK(7.2D0, B, FN, 5.0D0, G, 0.28D0, XI, ETA, PHI, 1,
     &            MSG, NWARN, IERR)
      CALL CHECKI('CWCHEK IERR', IERR, 0, NFAIL)
      CALL CHECKI('CWCHEK NWARN', NWARN, 2, NFAIL)
      CALL HAS('CWCHEK 1', MSG, 'a = 7.2 m is implausible', NFAIL)
      CALL CWCHEK(7.2D0, B, FN, 5.0D0, G, 0.28D0, XI, ETA, PHI, 2,
     &            MSG, NWARN, IERR)
      CALL HAS('CWCHEK 2', MSG, 'mu = 5 is implausible', NFAIL)
      CALL CWCHEK(6.0D-3, 6.0D-3, 80.0D3, FMU, G, 0.28D0, XI, ETA,
     &            PHI, 1, MSG, NWARN, IERR)
      CALL CHECKI('CWCHEK placeholders', NWARN, 0, NFAIL)
      IF (MSG .NE. ' ') THEN
         WRITE (*, *) 'CWCHEK without findings: ', MSG
         NFAIL = NFAIL + 1
      END IF
C
      CALL CWFORC(A, B, FN, FMU, G, 0.28D0, XI, ETA, PHI, NX, NY, 2,
     &            FX, FY, FMZ, WMAC, ADH, IERR)
      CALL CHECKI('CWFORC LOAD = 2', IERR, 2, NFAIL)
      CALL CWLAST(MSG)
      CALL HAS('CWFORC LOAD', MSG, 'exact_load', NFAIL)
      CALL CWFORC(A, B, FN, FMU, G, 0.28D0, XI, ETA, PHI, NX, 0, 0,
     &            FX, FY, FMZ, WMAC, ADH, IERR)
      CALL CHECKI('CWFORC NY = 0', IERR, 3, NFAIL)
      CALL CWLAST(MSG)
      CALL HAS('CWFORC ny', MSG, 'ny = 0', NFAIL)
      CALL CWFORC(A, B, FN, FMU, G, 0.28D0, XI, ETA, PHI, NX, NY, 0,
     &            FX, FY, FMZ, WMAC, ADH, IERR)
      CALL CHECKI('CWFORC', IERR, 0, NFAIL)
      CALL CWLAST(MSG)
      IF (MSG .NE. ' ') THEN
         WRITE (*, *) 'CWLAST after CWFORC: ', MSG
         NFAIL = NFAIL + 1
      END IF
      CALL CWFREE
C
      DSUM = 0
      WMSUM = 0
      WPSUM = 0
      WMAC = 0
      WMIC = 0
      DO 20 J = 1, NY
         DO 10 I = 1, NX
            WPAP(I, J) = 0
            WCON(I, J) = 0
            WPACC(I, J) = 0
            WCACC(I, J) = 0
   10    CONTINUE
   20 CONTINUE
      CALL CWACCU(NX, NY, -1.0D0, WMAC, WMIC, WPAP, WCON, DSUM, WMSUM,
     &            WPSUM, WPACC, WCACC, CKRUN, IERR)
      CALL CHECKI('CWACCU DIST = -1', IERR, 2, NFAIL)
      CALL CWLAST(MSG)
      CALL HAS('CWACCU', MSG, 'DIST = -1', NFAIL)
C
      IF (NFAIL .EQ. 0) THEN
         WRITE (*, *) 'all checks passed'
      ELSE
         WRITE (*, *) NFAIL, ' checks failed'
         STOP 1
      END IF
      END

      SUBROUTINE HAS(NAME, MSG, PART, NFAIL)
      CHARACTER*(*) NAME, MSG, PART
      INTEGER NFAIL
      IF (INDEX(MSG, PART) .EQ. 0) THEN
         WRITE (*, *) NAME, ': no "', PART, '" in: ', MSG
         NFAIL = NFAIL + 1
      END IF
      END

      SUBROUTINE CHECKI(NAME, IVAL, IWANT, NFAIL)
      CHARACTER*(*) NAME
      INTEGER IVAL, IWANT, NFAIL
      IF (IVAL .NE. IWANT) THEN
         WRITE (*, *) NAME, ': IERR =', IVAL, ', expected', IWANT
         NFAIL = NFAIL + 1
      END IF
      END
