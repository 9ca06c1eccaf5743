function L = kalker_flexibilities(a, b, G, nu)
%KALKER_FLEXIBILITIES  The simplified theory's flexibilities [L1 L2 L3] [m/Pa].
%   L = creepwork.kalker_flexibilities(a, b, G, nu): L1 = 8a/(3 C11 G),
%   L2 = 8a/(3 C22 G), L3 = pi a sqrt(a/b)/(4 C23 G) (cw_kalker_flexibilities).
  L = creepwork.call('kalker_flexibilities', a, b, G, nu);
end
