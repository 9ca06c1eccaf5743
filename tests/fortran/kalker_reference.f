C     KALKER_REFERENCE -- an independent FORTRAN 77 implementation of
C     Kalker's FASTSIM (Kalker 1982, "A fast algorithm for the simplified
C     theory of rolling contact", Vehicle System Dynamics 11, 1-13), for
C     the tests only. It does not call creepwork: it is a second
C     implementation, written from the published algorithm, that the
C     library must reproduce.
C
C     Normalised problem (Kalker 1982): unit disk X**2 + Y**2 <= 1,
C     traction bound G = 1 - X**2 - Y**2 (parabolic pressure), rigid slip
C     (UX - Y*FX, UY + X*FY), rolling towards +X (leading edge X = +AY).
C     Each strip [YB(J-1), YB(J)] is cut into MX equal elements over the
C     chord at its centre Y; the march starts at the leading edge with a
C     half step to the first element centre, takes the rigid slip at the
C     midpoint of each step and the bound at the element centre:
C        Q = P(previous) - H * W(step midpoint)
C        P = Q                  if |Q| <= G   (adhesion)
C        P = G * Q/|Q|          otherwise     (slip)
C     P is the traction on body 1 (the wheel) in units of mu*p0.

C     KRSTRP: Kalker's 1982 strip layout for MY strips and tolerance TOL,
C     identified by reproducing his published check values
C     (tests/data/kalker1982_checks.csv):
C       - the spin pole (X0, Y0) = (-UY/FY, UX/FX) is where the rigid slip
C         vanishes; inside the unit disk the strips are cut at YS = Y0,
C         otherwise at YS = 0;
C       - [-1, YS] and [YS, 1] get CEILING(MY*(1+YS)/2) and
C         CEILING(MY*(1-YS)/2) equal strips;
C       - with the pole inside, the strip next to YS on each side is
C         bisected towards YS while it is wider than 2*TOL.
C     Output: NS strips with boundaries YB(0:NS), NS <= MAXS. IERR = 1 if
C     MAXS is too small.
      SUBROUTINE KRSTRP(UX, UY, FX, FY, MY, TOL, MAXS, NS, YB, IERR)
      INTEGER MY, MAXS, NS, IERR
      DOUBLE PRECISION UX, UY, FX, FY, TOL, YB(0:MAXS)
      DOUBLE PRECISION YS, X0, Y0, WID
      INTEGER N1, N2, K, IS
      LOGICAL INSIDE
      IERR = 0
      YS = 0.0D0
      INSIDE = .FALSE.
      IF (FX .NE. 0.0D0 .AND. FY .NE. 0.0D0) THEN
         X0 = -UY/FY
         Y0 = UX/FX
         IF (X0*X0 + Y0*Y0 .LT. 1.0D0) THEN
            YS = Y0
            INSIDE = .TRUE.
         END IF
      END IF
      N1 = MAX(1, CEILING(0.5D0*MY*(1.0D0 + YS) - 1.0D-9))
      N2 = MAX(1, CEILING(0.5D0*MY*(1.0D0 - YS) - 1.0D-9))
      IF (N1 + N2 .GT. MAXS) THEN
         IERR = 1
         RETURN
      END IF
      NS = 0
      YB(0) = -1.0D0
      DO 10 K = 1, N1 - 1
         NS = NS + 1
         YB(NS) = -1.0D0 + (1.0D0 + YS)*K/N1
   10 CONTINUE
      NS = NS + 1
      YB(NS) = YS
      IS = NS
      DO 20 K = 1, N2
         NS = NS + 1
         YB(NS) = YS + (1.0D0 - YS)*K/N2
   20 CONTINUE
      YB(NS) = 1.0D0
      IF (.NOT. INSIDE) RETURN
C     Bisect the strip below YS (it ends at YB(IS)) ...
   30 CONTINUE
      WID = YB(IS) - YB(IS - 1)
      IF (WID .GT. 2.0D0*TOL .AND. WID .GT. 1.0D-12) THEN
         IF (NS + 1 .GT. MAXS) THEN
            IERR = 1
            RETURN
         END IF
         DO 40 K = NS, IS, -1
            YB(K + 1) = YB(K)
   40    CONTINUE
         YB(IS) = 0.5D0*(YB(IS - 1) + YS)
         NS = NS + 1
         IS = IS + 1
         GO TO 30
      END IF
C     ... and the strip above it (it starts at YB(IS)).
   50 CONTINUE
      WID = YB(IS + 1) - YB(IS)
      IF (WID .GT. 2.0D0*TOL .AND. WID .GT. 1.0D-12) THEN
         IF (NS + 1 .GT. MAXS) THEN
            IERR = 1
            RETURN
         END IF
         DO 60 K = NS, IS + 1, -1
            YB(K + 1) = YB(K)
   60    CONTINUE
         YB(IS + 1) = 0.5D0*(YS + YB(IS + 2))
         NS = NS + 1
         GO TO 50
      END IF
      RETURN
      END

C     KRSIM: the FASTSIM march on the strips YB(0:NS), MX elements each.
C     Outputs per element, in physical order (I = 1 at the trailing edge,
C     X increasing with I; J = 1 at Y = -1):
C       PX, PY   traction on the wheel / (mu p0)
C       IST      1 adhesion, 2 slip
C       XC       element centre X
C     and per strip: SPX, SPY = sums of PX, PY over the strip, SXPY = sum
C     of XC*PY, DXS = element length, WS = strip width, YC = strip centre.
C     TX, TY: the signs of Kalker's printed check values: TX = rail's
C     x-force / (mu N) = -(2/pi) sum(PX dX dY), TY = wheel's y-force /
C     (mu N) = +(2/pi) sum(PY dX dY).
      SUBROUTINE KRSIM(UX, UY, FX, FY, MX, NS, YB, PX, PY, IST, XC,
     &                 SPX, SPY, SXPY, DXS, WS, YC, TX, TY)
      INTEGER MX, NS, IST(MX, NS)
      DOUBLE PRECISION UX, UY, FX, FY, YB(0:NS)
      DOUBLE PRECISION PX(MX, NS), PY(MX, NS), XC(MX, NS)
      DOUBLE PRECISION SPX(NS), SPY(NS), SXPY(NS), DXS(NS), WS(NS)
      DOUBLE PRECISION YC(NS), TX, TY
      DOUBLE PRECISION PI
      PARAMETER (PI = 3.14159265358979323846D0)
      DOUBLE PRECISION Y, AY, DX, XPREV, X, H, XMID, QX, QY, G, Q, F
      DOUBLE PRECISION PXR, PYR, SUMX, SUMY
      INTEGER J, M, I
      SUMX = 0.0D0
      SUMY = 0.0D0
      DO 20 J = 1, NS
         Y = 0.5D0*(YB(J - 1) + YB(J))
         YC(J) = Y
         WS(J) = YB(J) - YB(J - 1)
         AY = SQRT(1.0D0 - Y*Y)
         DX = 2.0D0*AY/MX
         DXS(J) = DX
         SPX(J) = 0.0D0
         SPY(J) = 0.0D0
         SXPY(J) = 0.0D0
         PXR = 0.0D0
         PYR = 0.0D0
         XPREV = AY
         DO 10 M = 1, MX
            X = AY - (M - 0.5D0)*DX
            H = XPREV - X
            XMID = 0.5D0*(X + XPREV)
            QX = PXR - H*(UX - FX*Y)
            QY = PYR - H*(UY + FY*XMID)
            G = MAX(0.0D0, 1.0D0 - X*X - Y*Y)
            Q = SQRT(QX*QX + QY*QY)
            I = MX + 1 - M
            IF (Q .GT. G) THEN
               F = G/Q
               IST(I, J) = 2
            ELSE
               F = 1.0D0
               IST(I, J) = 1
            END IF
            PXR = F*QX
            PYR = F*QY
            PX(I, J) = PXR
            PY(I, J) = PYR
            XC(I, J) = X
            SPX(J) = SPX(J) + PXR
            SPY(J) = SPY(J) + PYR
            SXPY(J) = SXPY(J) + X*PYR
            XPREV = X
   10    CONTINUE
         SUMX = SUMX + DX*WS(J)*SPX(J)
         SUMY = SUMY + DX*WS(J)*SPY(J)
   20 CONTINUE
      TX = -2.0D0/PI*SUMX
      TY = 2.0D0/PI*SUMY
      RETURN
      END
