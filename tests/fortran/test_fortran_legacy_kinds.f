C     Wrong kinds passed to the legacy layer without interface blocks, as
C     a FORTRAN 77 caller can: what the library detects at run time.
C      - CWTYPE with a REAL*4 R: IERR /= 0;
C      - CWTYPE with an INTEGER*8 N: IERR /= 0 (IERR preset to -1);
C      - CWHERT with a REAL*4 FN followed by a zero REAL*4: the double it
C        reads is subnormal, so IERR = 2 (CW_ERR_INVALID_INPUT).
C     Compiled with -fallow-argument-mismatch: the mismatches are the test.
      PROGRAM KINDS
      REAL R4(2), PAIR(2)
      DOUBLE PRECISION R8(2), HA, HB, P0, APPR
      INTEGER N4(2), IERR, NFAIL
      INTEGER*8 N8(2)
      NFAIL = 0
      R4(1) = 1.0
      R4(2) = 2.0
      R8(1) = 1.0D0
      R8(2) = 2.0D0
      N4(1) = 1
      N4(2) = 2
      N8(1) = 1
      N8(2) = 2
      IERR = -1
      CALL CWTYPE(R8, N4, IERR)
      IF (IERR .NE. 0) THEN
         WRITE (*, *) 'CWTYPE rejected REAL*8, INTEGER*4: IERR =', IERR
         NFAIL = NFAIL + 1
      END IF
      IERR = -1
      CALL CWTYPE(R4, N4, IERR)
      IF (IERR .EQ. 0) THEN
         WRITE (*, *) 'CWTYPE accepted a REAL*4'
         NFAIL = NFAIL + 1
      END IF
      IERR = -1
      CALL CWTYPE(R8, N8, IERR)
      IF (IERR .EQ. 0) THEN
         WRITE (*, *) 'CWTYPE accepted an INTEGER*8'
         NFAIL = NFAIL + 1
      END IF
      PAIR(1) = 1.0E5
      PAIR(2) = 0.0
      IERR = -1
      CALL CWHERT(0.8D0, 1.9D0, PAIR, 1.1D11, HA, HB, P0, APPR, IERR)
      IF (IERR .NE. 2) THEN
         WRITE (*, *) 'CWHERT with a REAL*4 load: IERR =', IERR
         NFAIL = NFAIL + 1
      END IF
      IF (NFAIL .NE. 0) STOP 1
      WRITE (*, '(A)') 'wrong kinds detected'
      END
