function r = jacobian(varargin)
%JACOBIAN  A solve and its 4 x 4 Jacobian.
%   R = creepwork.jacobian(...) takes creepwork.solve's arguments and returns
%   its result with R.jacobian(i, k) = d(row i)/d(column k), rows Fx, Fy,
%   Mz, W_macro, columns xi_x, xi_y, phi, normal_force, in SI units
%   (cw_solver_solve_jacobian); e.g. R.jacobian(1, 1) = dFx/dxi_x [N].
%   Without 'fields', true, only the totals are computed.
  [p, opt] = creepwork.inputs(varargin{:});
  fields = any(strcmp(varargin(cellfun(@ischar, varargin)), 'fields')) && opt.fields;
  r = creepwork.call('solve', p, opt.grid, fields, true);
end
