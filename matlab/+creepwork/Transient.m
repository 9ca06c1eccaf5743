classdef Transient < handle
%TRANSIENT  Transient rolling: rolling contact with memory (cw_transient).
%   T = creepwork.Transient(GRID, ...) makes the transient contact of a gap
%   grid (GRID a struct of cw_grid fields with 'kind', 'gap'; cell (i, j)
%   centred at x0 + (i-1)*dx, y0 + (j-1)*dy) from creepwork.solve's
%   parameters: 'gap' (nx-by-ny [m]), 'N' (or 'normal_load', 'approach'),
%   'G', 'nu', 'mu', 'tolerance', ...; 'model', 'fastsim' takes FASTSIM's
%   transient form instead of the exact theory (the default). An elliptic
%   contact: GRID of kind 'uniform' (nx, ny, box_scale) with 'a', 'b', 'N'.
%   The normal problem is solved here and the state starts from zero
%   tractions.
%
%   R = T.step('dq', DQ, 'xi_x', XI, ...) computes one step from the
%   committed state (a trial; repeated after T.rewind() it gives the same
%   bits): DQ [m] rolled (0 <= DQ <= dx; 0 is a shift, 'xi_x', 'xi_y' then
%   the rigid shift [m] and 'phi' the rotation [rad]); 'Fx' (and 'Fy') [N]
%   prescribed find xi_x (and xi_y). R holds cw_transient_result's fields
%   (xi_x, Fx, Mz, n_adhesion, n_slip, W_step, ...). T.commit() makes the
%   trial the state; T.rewind() drops it. T.start_steady(...) starts from
%   the steady solution of the same inputs, T.start_zero() from zero.
%   W = T.save() gives the committed state (uint64 words), T.restore(W)
%   takes it back. F = T.fields() gives the last step's x, y, pz, px, py,
%   sx, sy (sx, sy the slip of the step [m]), work (each element's
%   frictional work over the step [J], summing to W_step) and state as
%   nx-by-ny matrices. J = T.jacobian() is the last step's derivative (the
%   exact model's): J(r, c) = d(output r)/d(input c), rows Fx, Fy, Mz and
%   columns xi_x, xi_y, phi with creepages given (a prescribed force and
%   its found creepage trade places). T.set_coordinates('world') runs
%   world-fixed (the exact model's; 'contact' is the default) from zero
%   tractions. M = T.add_wear('law', 0, ...) adds the last step's wear by
%   cw_wear_params' fields (after the commit) and returns its mass [kg];
%   W = T.wear() gives the accumulated mass and mass_map [kg];
%   T.reset_wear() clears it. delete(T) (or clearing T) frees it.
%
%     t = creepwork.Transient(grid, 'gap', h, 'N', 0.4705, 'G', 1e6, ...
%                             'nu', 0.28, 'mu', 0.4013);
%     r = t.step('dq', 0, 'Fx', -0.124);  t.commit();   % a Cattaneo shift
%     r = t.step('dq', 2.5e-4, 'Fx', -0.124);  t.commit();
  properties (SetAccess = private)
    nx = 0;  % cells along x
    ny = 0;  % cells along y
  end
  properties (Access = private)
    id = 0;
  end
  methods
    function obj = Transient(grid, varargin)
      if nargin < 1 || ~isstruct(grid)
        error('creepwork:usage', ['grid: creepwork.Transient(GRID, ...) needs the gap ' ...
                                  'grid as a struct (kind ''gap'', nx, ny, x0, y0, dx, dy)']);
      end
      [p, opt] = creepwork.inputs(varargin{:});
      if ~isempty(opt.grid)
        error('creepwork:usage', 'grid: give it as the first argument, not as ''grid''');
      end
      if ~isfield(p, 'model')
        p.model = 'exact';
      end
      [obj.id, obj.nx, obj.ny] = creepwork.call('transient_create', grid, p);
    end
    function r = step(obj, varargin)
      r = creepwork.call('transient_step', obj.id, creepwork.Transient.input(varargin), false);
    end
    function r = start_steady(obj, varargin)
      r = creepwork.call('transient_start_steady', obj.id, creepwork.Transient.input(varargin));
    end
    function start_zero(obj)
      creepwork.call('transient_start_zero', obj.id);
    end
    function commit(obj)
      creepwork.call('transient_commit', obj.id);
    end
    function rewind(obj)
      creepwork.call('transient_rewind', obj.id);
    end
    function w = save(obj)
      w = creepwork.call('transient_save', obj.id);
    end
    function restore(obj, w)
      creepwork.call('transient_restore', obj.id, w);
    end
    function f = fields(obj)
      f = creepwork.call('transient_fields', obj.id);
    end
    function J = jacobian(obj)
      J = creepwork.call('transient_jacobian', obj.id);
    end
    function set_coordinates(obj, coordinates)
      creepwork.call('transient_set_coordinates', obj.id, coordinates);
    end
    function m = add_wear(obj, varargin)
      if mod(numel(varargin), 2) ~= 0 || ~all(cellfun(@ischar, varargin(1:2:end)))
        error('creepwork:usage', 'add_wear: expected name-value pairs of cw_wear_params');
      end
      law = struct();
      for k = 1:2:numel(varargin)
        law.(varargin{k}) = varargin{k + 1};
      end
      m = creepwork.call('transient_add_wear', obj.id, law);
    end
    function w = wear(obj)
      w = creepwork.call('transient_wear', obj.id);
    end
    function reset_wear(obj)
      creepwork.call('transient_reset_wear', obj.id);
    end
    function delete(obj)
      if obj.id
        creepwork.call('transient_destroy', obj.id);
        obj.id = 0;
      end
    end
  end
  methods (Static, Access = private)
    function s = input(args)
      % Name-value pairs as a cw_transient_input: Fx (and Fy) set what is
      % prescribed.
      if mod(numel(args), 2) ~= 0 || ~all(cellfun(@ischar, args(1:2:end)))
        error('creepwork:usage', 'step: expected name-value pairs (dq, xi_x, xi_y, phi, Fx, Fy)');
      end
      s = struct();
      for k = 1:2:numel(args)
        s.(args{k}) = args{k + 1};
      end
      c = creepwork.constants();
      if isfield(s, 'Fy') && ~isfield(s, 'Fx')
        error('creepwork:usage', 'Fy: needs Fx (both forces are prescribed together)');
      end
      if isfield(s, 'Fy')
        s.prescribe = c.CW_PRESCRIBE_FORCES;
      elseif isfield(s, 'Fx')
        s.prescribe = c.CW_PRESCRIBE_FX;
      end
    end
  end
end
