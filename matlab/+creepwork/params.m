function p = params(which)
%PARAMS  The library's defaults of the contact parameters (cw_params_init).
%   P = creepwork.params() is a struct with every field of cw_params at its
%   default (steel: G = 82e9 Pa, nu = 0.28; mu = 0.3; a = b = 6e-3 m,
%   N = 80e3 N; FASTSIM; enumerations as numbers: creepwork.constants names
%   them). P = creepwork.params('cw_grid') gives the grid's defaults.
  if nargin < 1
    which = 'cw_params';
  end
  p = creepwork.call('defaults', which);
end
