C     Vehicle loop, FORTRAN 77 version (legacy layer, no module): a wheel
C     on tangent track while the wheelset hunts. Same loop as
C     vehicle_loop.c: every step computes the creepages, CALL CWSOLM
C     solves the contact and CALL CWACCU adds the step's work (V*dt of
C     rolling, paper eqs. 35, 37) into the caller's arrays; at the end the
C     lateral work profile (accumulated energy-consistent work per unit
C     width, J/m) is written. The strips of the Kalker grid are NY equal
C     strips across [-B, B].
C     creepwork_legacy.inc (installed in include/creepwork/fortran)
C     declares the legacy routines EXTERNAL and lists their arguments.
      PROGRAM VLOOP
      IMPLICIT DOUBLE PRECISION (A-H, O-Z)
      INCLUDE 'creepwork_legacy.inc'
      PARAMETER (NX = 20, NY = 20, NSTEPS = 3000)
      PARAMETER (PI = 3.14159265358979323846D0)
      DIMENSION PX(NX, NY), PY(NX, NY), SX(NX, NY), SY(NX, NY)
      DIMENSION ZMAP(NX, NY), WPAP(NX, NY), WCON(NX, NY)
      DIMENSION WPACC(NX, NY), WCACC(NX, NY)
      INTEGER ISTATE(NX, NY)
C     V = 30 m/s, DT = 1 ms; hunting at 2 Hz, 3 mm; conicity 0.15,
C     rolling radius 0.46 m; contact 6 x 4 mm, 60 kN, mu 0.35, steel.
      V = 30.0D0
      DT = 1.0D-3
      OMEGA = 2.0D0*PI*2.0D0
      Y0 = 3.0D-3
      CLAMB = 0.15D0
      R0 = 0.46D0
      A = 6.0D-3
      B = 4.0D-3
      FN = 60.0D3
      FMU = 0.35D0
      G = 82.0D9
      PNU = 0.28D0
      DSUM = 0.0D0
      WMSUM = 0.0D0
      WPSUM = 0.0D0
      CKRUN = 0.0D0
      DO 20 J = 1, NY
         DO 10 I = 1, NX
            WPACC(I, J) = 0.0D0
            WCACC(I, J) = 0.0D0
   10    CONTINUE
   20 CONTINUE
C
      DO 100 K = 1, NSTEPS
         T = K*DT
         Y = Y0*SIN(OMEGA*T)
         YDOT = Y0*OMEGA*COS(OMEGA*T)
         YAW = 0.7D0*YDOT/V
         XI = -CLAMB*Y/R0
         ETA = YDOT/V - YAW
         PHI = (0.05D0 + 10.0D0*Y)/R0
         CALL CWSOLM(A, B, FN, FMU, G, PNU, XI, ETA, PHI, NX, NY,
     &               FX, FY, FMZ, WMAC, WMIC, CK, PX, PY, SX, SY,
     &               ZMAP, WPAP, WCON, ISTATE, IERR)
         IF (IERR .NE. 0) THEN
            WRITE (*, *) 'CWSOLM failed, IERR =', IERR
            STOP 1
         END IF
         CALL CWACCU(NX, NY, V*DT, WMAC, WMIC, WPAP, WCON, DSUM, WMSUM,
     &               WPSUM, WPACC, WCACC, CKRUN, IERR)
         IF (IERR .NE. 0) THEN
            WRITE (*, *) 'CWACCU failed, IERR =', IERR
            STOP 1
         END IF
  100 CONTINUE
C
      WRITE (*, '(A, I0, A, F0.1, A)') '# creepwork vehicle loop: ',
     &   NSTEPS, ' steps, ', DSUM, ' m rolled'
      WRITE (*, '(A, 1P, E16.9, A, E16.9, A, 0P, F12.9)')
     &   '# W_macro = ', WMSUM, ' J, W_micro = ', WPSUM, ' J, K = ',
     &   CKRUN
      WRITE (*, '(A)') '# strip  y [m]  work per unit width [J/m]'
      WIDTH = 2.0D0*B/NY
      DO 120 J = 1, NY
         YJ = B*(-1.0D0 + (2*J - 1)*1.0D0/NY)
         S = 0.0D0
         DO 110 I = 1, NX
            S = S + WCACC(I, J)
  110    CONTINUE
         WRITE (*, '(I3, 1X, 1P, E12.5, 1X, E16.9)') J, YJ, S/WIDTH
  120 CONTINUE
      END
