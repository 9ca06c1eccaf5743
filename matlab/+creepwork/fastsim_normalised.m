function [tx, ty] = fastsim_normalised(ux, uy, fx, fy, mx, my, tol)
%FASTSIM_NORMALISED  Kalker's original normalised FASTSIM (1982, his SIM routine).
%   [TX, TY] = creepwork.fastsim_normalised(ux, uy, fx, fy, mx, my, tol):
%   normalised creepages ux, uy and spin terms fx, fy on the unit disk, mx
%   elements per strip, my strips cut at the spin pole (tol as Kalker's).
%   TX, TY with Kalker's published signs: TX = -Fx/(mu N), TY = +Fy/(mu N)
%   in creepwork.solve's convention (cw_fastsim_normalised).
  t = creepwork.call('fastsim_normalised', [ux, uy, fx, fy, mx, my, tol]);
  tx = t(1);
  ty = t(2);
end
