function c = kalker_coefficients(a_over_b, nu)
%KALKER_COEFFICIENTS  Kalker's creepage coefficients [C11 C22 C23 C33] [-].
%   C = creepwork.kalker_coefficients(a_over_b, nu) for a/b in [1e-3, 1e3]
%   and nu in [0, 0.5] (Kalker 1990, Table E.3, interpolated as CONTACT
%   does; cw_kalker_coefficients).
  c = creepwork.call('kalker_coefficients', a_over_b, nu);
end
