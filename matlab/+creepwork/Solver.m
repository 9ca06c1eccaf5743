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
