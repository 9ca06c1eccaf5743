function h = hertz(A, B, N, E_star)
%HERTZ  Hertz contact of elastically similar bodies (cw_hertz_solve).
%   H = creepwork.hertz(A, B, N, E_star): A, B > 0 [1/m] the coefficients of
%   the gap z = A x^2 + B y^2, i.e. HALF the relative curvatures,
%   A = (1/R1x + 1/R2x)/2 along x (rolling); N [N]; E_star [Pa]
%   (G/(1 - nu) for identical materials). H.a, H.b semi-axes [m], H.p0
%   maximum pressure [Pa], H.approach [m]. Example: a 0.457 m wheel on a
%   0.3 m rail crown, creepwork.hertz(1/(2*0.457), 1/(2*0.3), 100e3,
%   82e9/(1 - 0.28)): a = 7.170 mm, b = 5.417 mm, p0 = 1229 MPa.
  v = creepwork.call('hertz', [A, B, N, E_star]);
  h = struct('a', v(1), 'b', v(2), 'p0', v(3), 'approach', v(4));
end
