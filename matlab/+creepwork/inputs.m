function [p, opt] = inputs(varargin)
%INPUTS  The inputs of creepwork.solve, solve_many, jacobian and Solver methods.
%   [P, OPT] = creepwork.inputs(...) splits the arguments into the contact's
%   parameters P (a struct of cw_params fields: a, b, N or normal_force, mu,
%   G, nu, xi_x, xi_y, phi, model, ...) and the options OPT (grid, fields,
%   full, threads). The arguments are an optional struct of parameters
%   followed by name-value pairs, which override it. Used by the other
%   functions of the package; users call those.
%
%   Without a 'grid', the exact model gets the library's grid for it
%   (cw_grid_init_model, as every door): uniform, 24 x 24 elements over 1.2
%   times the semi-axes (20 across the ellipse, two guard cells on each
%   side); the other models Kalker's strips, 20 x 20.
  p = struct();
  first = 1;
  if nargin >= 1 && isstruct(varargin{1})
    p = varargin{1};
    first = 2;
  end
  opt = struct('grid', [], 'fields', true, 'full', false, 'threads', 0);
  rest = varargin(first:end);
  if mod(numel(rest), 2) ~= 0
    error('creepwork:usage', 'arguments after the struct come in name-value pairs');
  end
  for k = 1:2:numel(rest)
    name = rest{k};
    if ~ischar(name)
      error('creepwork:usage', 'argument %d: expected a parameter name', first + k - 1);
    end
    if isfield(opt, name)
      opt.(name) = rest{k + 1};
    else
      p.(name) = rest{k + 1};
    end
  end
  if isfield(p, 'polach')
    p = polach_law(p);
  end
  if isempty(opt.grid) && isfield(p, 'model') && is_exact(p.model)
    opt.grid = creepwork.call('model_grid', 'exact');
  end
end

function yes = is_exact(model)
  if ischar(model)
    yes = strcmp(creepwork.call('input_name', model), 'exact');
  else
    c = creepwork.constants();
    yes = ~isempty(model) && all(model(:) == c.CW_MODEL_EXACT);
  end
end

% 'polach', [mu0 A B] (B in s/m): the fields the library's cw_friction_polach
% writes (the exponential law: mu = A mu0, mu_e1 = (1 - A) mu0, s_h1 = ln2/B).
function p = polach_law(p)
  names = {'friction_law', 'mu', 'mu_e1', 's_h1', 'mu_e2', 's_h2'};
  for k = 1:numel(names)
    if isfield(p, names{k})
      error('creepwork:usage', 'polach sets the friction law and mu: %s cannot be given with it', ...
            names{k});
    end
  end
  law = creepwork.call('friction_polach', double(p.polach));
  p = rmfield(p, 'polach');
  for k = 1:numel(names)
    p.(names{k}) = law.(names{k});
  end
end
