C     Rail wear loop, FORTRAN 77 on the legacy layer (no module): 10000
C     wheel passes over one rail section while the wheelsets hunt, the
C     rail profile updated every 1000 passes.
C
C     Each pass is one axle passage. The wheelset's lateral position is
C     Y = Y0 SIN(THETA), the hunting phase THETA spread evenly over the
C     passes (a golden-ratio sequence), so the positions follow the
C     hunting distribution (dense near +-Y0). From it: the contact point
C     on the rail head S0 (it moves 1.5 times as far as the wheelset), the
C     contact angle GAMMA on the 300 mm rail crown, the semi-axis B
C     (wider on the flatter crown centre), and the creepages of a conical
C     wheel: XI = -LAMBDA Y / R0, ETA from the yaw lag, PHI = SIN(GAMMA)/R0.
C     CALL CWWEAR gives the depth per pass of each strip (USFD, default
C     coefficients); CALL CWWPRF adds it to the rail profile's depth (PDH
C     vertical, PDN normal to the surface); every 1000 passes CALL CWWUPD
C     lowers the rail head by the smoothed vertical depth and the depth
C     is started again. The program stops with a message if a routine
C     fails or the update does not conserve the worn volume.
      PROGRAM WLOOP
      IMPLICIT DOUBLE PRECISION (A-H, O-Z)
      INCLUDE 'creepwork_legacy.inc'
      PARAMETER (NX = 16, NY = 16, NS = 81)
      PARAMETER (NPASS = 10000, NUPD = 1000)
      PARAMETER (PI = 3.14159265358979323846D0)
      DIMENSION YS(NY), DYS(NY), DEPTH(NY)
      DIMENSION S(NS), Z(NS), Z0(NS), ZNEW(NS), PDN(NS), PDH(NS), W(NS)
C     Hunting: amplitude 4 mm, wavelength 20 m at 30 m/s. Wheel: radius
C     0.46 m, conicity 0.2. Contact: 6 mm x 4 mm at the crown centre,
C     60 kN, mu 0.35, steel.
      Y0 = 4.0D-3
      V = 30.0D0
      WAVEL = 20.0D0
      R0 = 0.46D0
      CLAMB = 0.2D0
      RRAIL = 0.3D0
      A = 6.0D-3
      FN = 60.0D3
      FMU = 0.35D0
      G = 82.0D9
      PNU = 0.28D0
      GOLD = 0.5D0*(SQRT(5.0D0) - 1.0D0)
C     Rail profile: nodes every 0.5 mm over +-20 mm of the head, heights
C     of the 300 mm crown; W = cell widths (all 0.5 mm here).
      DO 10 K = 1, NS
         S(K) = -20.0D-3 + 0.5D-3*(K - 1)
         Z(K) = -S(K)**2/(2.0D0*RRAIL)
         Z0(K) = Z(K)
         W(K) = 0.5D-3
         PDN(K) = 0.0D0
         PDH(K) = 0.0D0
   10 CONTINUE
      SMOOTH = 0.5D-3
      WRITE (*, '(A)') '# creepwork rail wear loop: 10000 passes,'
     &   // ' USFD, profile updated every 1000'
      WRITE (*, '(A)') '# passes  max depth [m]  worn section [m2]'
     &   // '  removed section [m2]  rail wear max [m]'
C
      DO 100 K = 1, NPASS
         THETA = 2.0D0*PI*MOD(K*GOLD, 1.0D0)
         Y = Y0*SIN(THETA)
         YDOT = Y0*(2.0D0*PI*V/WAVEL)*COS(THETA)
         S0 = 1.5D0*Y
         GAMMA = S0/RRAIL
         B = 4.0D-3*(1.0D0 - 8.0D0*ABS(S0))
         XI = -CLAMB*Y/R0
         ETA = 0.3D0*YDOT/V
         PHI = SIN(GAMMA)/R0
         CALL CWWEAR(A, B, FN, FMU, G, PNU, XI, ETA, PHI, NX, NY, 0, V,
     &               YS, DYS, DEPTH, WMASS, IERR)
         IF (IERR .NE. 0) THEN
            WRITE (*, *) 'CWWEAR failed, IERR =', IERR
            STOP 1
         END IF
         CALL CWWPRF(NS, S, NY, YS, DYS, DEPTH, S0, 1, GAMMA, 1.0D0,
     &               PDN, PDH, IERR)
         IF (IERR .NE. 0) THEN
            WRITE (*, *) 'CWWPRF failed, IERR =', IERR
            STOP 1
         END IF
         IF (MOD(K, NUPD) .EQ. 0) THEN
            CALL CWWUPD(NS, S, Z, PDH, SMOOTH, ZNEW, IERR)
            IF (IERR .NE. 0) THEN
               WRITE (*, *) 'CWWUPD failed, IERR =', IERR
               STOP 1
            END IF
            DMAX = 0.0D0
            WORN = 0.0D0
            REMOV = 0.0D0
            TMAX = 0.0D0
            DO 20 I = 1, NS
               DMAX = MAX(DMAX, PDH(I))
               WORN = WORN + PDH(I)*W(I)
               REMOV = REMOV + (Z(I) - ZNEW(I))*W(I)
               Z(I) = ZNEW(I)
               TMAX = MAX(TMAX, Z0(I) - Z(I))
               PDN(I) = 0.0D0
               PDH(I) = 0.0D0
   20       CONTINUE
            IF (ABS(REMOV - WORN) .GT. 1.0D-12*WORN) THEN
               WRITE (*, *) 'the update lost volume:', WORN, REMOV
               STOP 1
            END IF
            WRITE (*, '(I7, 1P, 4E16.6)') K, DMAX, WORN, REMOV, TMAX
         END IF
  100 CONTINUE
C
      WRITE (*, '(A)') '# s [m]  rail wear depth after 10000 passes [m]'
      DO 120 I = 1, NS, 4
         WRITE (*, '(1P, E12.4, E16.6)') S(I), Z0(I) - Z(I)
  120 CONTINUE
      END
