C     A FORTRAN 77 caller of the legacy layer outside the creepwork tree:
C     no module, no -I, only -L<prefix>/lib -lcreepwork_fortran -lcreepwork.
C     Kalker's 1982 check row 4 (kalker1982_checks.csv): TX = 0.5684.
C     CWFORC in full sliding with LOAD = 1: |FX| = FMU FN (Coulomb, with
C     the discrete load equal to FN). CWLAST after CWKALK with PNU = 0.6
C     names nu.
      PROGRAM LEGACY
      DOUBLE PRECISION TX, TY, FX, FY, FMZ, WMAC, ADH, C(4)
      INTEGER IERR
      CHARACTER*120 MSG
      CALL CWFSIM(1.0D0, -2.0D0, 2.0D0, 4.0D0, 5, 5, 3.0D0, TX, TY,
     &            IERR)
      WRITE (*, '(A, F7.4, A, F7.4)') 'CWFSIM: TX =', TX, ' TY =', TY
      IF (IERR .NE. 0 .OR. ABS(TX - 0.5684D0) .GT. 0.5D-4) STOP 1
      CALL CWFORC(7.17D-3, 5.42D-3, 100.0D3, 0.3D0, 82.0D9, 0.28D0,
     &            0.3D0, 0.0D0, 0.0D0, 20, 20, 1, FX, FY, FMZ, WMAC,
     &            ADH, IERR)
      WRITE (*, '(A, F12.4)') 'CWFORC: -FX / (mu N) =', -FX/30.0D3
      IF (IERR .NE. 0 .OR. ABS(-FX - 30.0D3) .GT. 30.0D3*1.0D-12) STOP 2
      CALL CWFREE
      CALL CWKALK(1.0D0, 0.6D0, C(1), C(2), C(3), C(4), IERR)
      CALL CWLAST(MSG)
      WRITE (*, '(A, A)') 'CWLAST: ', MSG(1:LEN_TRIM(MSG))
      IF (IERR .NE. 2 .OR. INDEX(MSG, 'nu = 0.6') .EQ. 0) STOP 3
      END
