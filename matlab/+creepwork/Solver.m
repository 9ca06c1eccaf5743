classdef Solver < handle
%SOLVER  A solver for one grid, reused for many solves (cw_solver).
%   S = creepwork.Solver(GRID) makes one (GRID a struct of cw_grid fields,
%   as creepwork.solve's 'grid'; none: Kalker's strips 20 x 20). Then
%   R = S.solve(...) takes creepwork.solve's parameters and 'fields';
%   R = S.jacobian(...) adds R.jacobian. T = S.temperature('rolling_speed',
%   V, ...) gives both bodies' surface temperatures of the last solve
%   (which needs 'fields', true; the fields of cw_temperature_params as
%   name-value pairs, e.g. 'T0_1', 'conductivity_2', 'discretisation',
%   'contact'; body 1 the rail, body 2 the wheel): T.T_max_1, T.x_max_1,
%   ..., and T.rail, T.wheel, T.heat as nx-by-ny matrices.
%   [R, T] = S.solve_mu_T(MU_T, TEMPERATURE, ...) solves with friction
%   that depends on the temperature (help creepwork.Solver.solve_mu_T).
%   D = S.damage('k_yield', K, ...) gives the damage indices: D.rcf_index_max,
%   D.FI_surf, D.T_gamma, D.wlrm_damage, ..., D.rcf_index and
%   D.t_gamma_density (nx-by-ny). The exact model starts from the
%   solver's last solution (warm_start = 1, the default): loops over
%   nearby contacts converge in fewer iterations. delete(S) (or clearing
%   S) frees it.
%
%     s = creepwork.Solver(struct('kind', 'uniform', 'nx', 24, 'ny', 24, ...
%                                 'box_scale', 1.2));
%     for xi = linspace(1e-4, 2e-3, 20)
%       r = s.solve('a', 7e-3, 'b', 5e-3, 'N', 100e3, 'xi_x', xi, ...
%                   'model', 'exact', 'fields', false);
%     end
%     delete(s);
  properties (SetAccess = private)
    nx = 0;  % elements along x
    ny = 0;  % strips along y
  end
  properties (Access = private)
    id = 0;
  end
  methods
    function obj = Solver(grid)
      if nargin < 1
        grid = [];
      end
      [obj.id, obj.nx, obj.ny] = creepwork.call('solver_create', grid);
    end
    function r = solve(obj, varargin)
      [p, opt] = creepwork.inputs(varargin{:});
      r = creepwork.call('solver_solve', obj.id, p, opt.fields, false);
    end
    function r = jacobian(obj, varargin)
      [p, opt] = creepwork.inputs(varargin{:});
      fields = any(strcmp(varargin(cellfun(@ischar, varargin)), 'fields')) && opt.fields;
      r = creepwork.call('solver_solve', obj.id, p, fields, true);
    end
    function t = temperature(obj, varargin)
      t = creepwork.call('solver_temperature', obj.id, creepwork.Solver.pairs(varargin));
    end
    function [r, t] = solve_mu_T(obj, mu_T, temperature, varargin)
      %SOLVE_MU_T  Friction that depends on the surface temperature.
      %   [R, T] = S.solve_mu_T(MU_T, TEMPERATURE, ...) solves with mu
      %   piecewise linear through the rows [T mu] of MU_T (deg C; e.g.
      %   [0 0.33; 400 0.14], CONTACT's L=6) in the rail's temperature,
      %   TEMPERATURE a struct of cw_temperature_params fields (or []), then
      %   creepwork.solve's parameters (model 'exact' on a uniform grid), in
      %   cw_temperature_solve's loop of solve and temperature. R is the
      %   last solve with its fields, T its temperatures (T.iterations: the
      %   passes).
      p = creepwork.inputs(varargin{:});
      if isempty(temperature)
        temperature = struct();
      end
      [t, r] = creepwork.call('solver_solve_mu_T', obj.id, p, temperature, mu_T);
    end
    function d = damage(obj, varargin)
      d = creepwork.call('solver_damage', obj.id, creepwork.Solver.pairs(varargin));
    end
    function delete(obj)
      if obj.id
        creepwork.call('solver_destroy', obj.id);
        obj.id = 0;
      end
    end
  end
  methods (Static, Access = private)
    function s = pairs(args)
      % Name-value pairs as a struct (a struct given alone is taken as it is).
      if numel(args) == 1 && isstruct(args{1})
        s = args{1};
        return;
      end
      if mod(numel(args), 2) ~= 0 || ~all(cellfun(@ischar, args(1:2:end)))
        error('creepwork:usage', 'expected name-value pairs');
      end
      s = struct();
      for k = 1:2:numel(args)
        s.(args{k}) = args{k + 1};
      end
    end
  end
end
