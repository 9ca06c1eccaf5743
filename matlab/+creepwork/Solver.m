classdef Solver < handle
%SOLVER  A solver for one grid, reused for many solves (cw_solver).
%   S = creepwork.Solver(GRID) makes one (GRID a struct of cw_grid fields,
%   as creepwork.solve's 'grid'; none: Kalker's strips 20 x 20). Then
%   R = S.solve(...) takes creepwork.solve's parameters and 'fields';
%   R = S.jacobian(...) adds R.jacobian. The exact model starts from the
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
    function delete(obj)
      if obj.id
        creepwork.call('solver_destroy', obj.id);
        obj.id = 0;
      end
    end
  end
end
