% The rules every door shares, through the Octave door: a gap matrix that is
% not nx-by-ny is an error naming the axes (h.' was solved as another
% contact: 8 patches for 2); a gap in millimetres warns; a, b and N are
% required as the CLI requires them; messages name the load as typed; one
% spelling for every value (the library's aliases); a field of the grid
% given with the contact points at the grid.
function test_policy()
  grid = struct('kind', 'gap', 'nx', 30, 'ny', 56, 'x0', -5e-3, 'y0', -12e-3, ...
                'dx', 0.35e-3, 'dy', 0.45e-3);
  [x, y] = ndgrid(grid.x0 + grid.dx * (0:29), grid.y0 + grid.dy * (0:55));
  h = min(x.^2 / 0.9 + (y + 6e-3).^2 / 0.5, x.^2 / 0.8 + (y - 6e-3).^2 / 0.3 + 2e-6);
  gap = {'N', 60e3, 'xi_y', -3e-4, 'model', 'exact', 'grid', grid, 'fields', false};
  r = creepwork.solve(gap{:}, 'gap', h);
  assert(r.n_patches == 2);
  expect_error(@() creepwork.solve(gap{:}, 'gap', h.'), 'creepwork:CW_ERR_INVALID_INPUT', ...
               ['gap is 56-by-30; the grid''s nx = 30 cells along x and ny = 56 along y need an ', ...
                'nx-by-ny matrix \(30-by-56\): x along the first dimension.*gap\.'' has that size']);
  flat = creepwork.solve(gap{:}, 'gap', h(:));  % column-major: the library's [i + j*nx]
  assert(flat.Fy == r.Fy && flat.p_max == r.p_max);

  % heights in millimetres: a warning naming gap, the spread to 1 um
  lastwarn('', '');
  creepwork.solve(gap{:}, 'gap', h);
  [~, id] = lastwarn();
  assert(isempty(id), 'a gap in metres warned');
  creepwork.solve(gap{:}, 'gap', 1e3 * h);
  [msg, id] = lastwarn();
  assert(strcmp(id, 'creepwork:implausibleUnits'), id);
  spread = round(1e9 * (max(h(:)) - min(h(:)))) / 1e6;
  assert(~isempty(strfind(msg, sprintf('gap = %.10g m is implausible for a wheel-rail contact', spread))), msg);

  % a, b and N required
  expect_error(@() creepwork.solve('xi_x', 1e-3), 'creepwork:missingInput', ...
               '^a, b, N: missing: the contact''s semi-axes and load have no sensible default');
  expect_error(@() creepwork.solve('a', 7e-3, 'b', 5e-3, 'xi_x', 1e-3), 'creepwork:missingInput', '^N: missing');
  expect_error(@() creepwork.solve_many('a', 7e-3, 'N', 1e5, 'xi_x', [1e-3 2e-3]), ...
               'creepwork:missingInput', '^b: missing');
  s = creepwork.Solver();
  expect_error(@() s.solve('b', 5e-3, 'N', 1e5), 'creepwork:missingInput', '^a: missing');
  delete(s);
  creepwork.solve('a', 7e-3, 'b', 5e-3, 'normal_force', 1e5, 'fields', false);

  % the load as typed; the grid's field pointed at the grid
  base = {'a', 7e-3, 'b', 5e-3};
  expect_error(@() creepwork.solve(base{:}, 'N', -1), 'creepwork:CW_ERR_INVALID_INPUT', '^N = -1 is invalid');
  expect_error(@() creepwork.solve(base{:}, 'normal_force', -1), 'creepwork:CW_ERR_INVALID_INPUT', ...
               '^normal_force = -1 is invalid');
  m = creepwork.solve_many(base{:}, 'N', [1e5 -1]);
  assert(strncmp(m.message{2}, 'N = -1 is invalid', 17), m.message{2});
  lastwarn('', '');
  creepwork.solve(base{:}, 'N', 100, 'fields', false);
  [msg, id] = lastwarn();
  assert(strcmp(id, 'creepwork:implausibleUnits') && ~isempty(regexp(msg, '(^|: )N = 100 N is implausible', 'once')), msg);
  expect_error(@() creepwork.solve(base{:}, 'N', 1e5, 'nx', 30), 'creepwork:unknownField', ...
               '''nx'' is not a field of cw_params.*it is a field of the grid');

  % one spelling: the library's aliases, the same bits
  ref = creepwork.solve(base{:}, 'N', 1e5, 'xi_x', 1e-3, 'phi', 0.5, 'fields', false);
  a1 = creepwork.solve(base{:}, 'N', 1e5, 'xi_x', 1e-3, 'spin', 0.5, 'fields', false);
  a2 = creepwork.solve(base{:}, 'N', 1e5, 'xi_x', 1e-3, 'phi', 0.5, 'model', 'fast', ...
                       'grid', struct('kind', 'Strips'), 'fields', false);
  assert(a1.Fy == ref.Fy && a2.Fy == ref.Fy);
  f1 = creepwork.solve(gap{:}, 'gap', h, 'model', 'fastsim', 'normal_method', 'semi_hertz');
  f2 = creepwork.solve(gap{:}, 'gap', h, 'model', 'fastsim', 'normal_method', 'semi-hertz');
  assert(f1.Fx == f2.Fx && f1.p_max == f2.p_max);
  % the exact model's default grid is the library's (cw_grid_init_model)
  e = creepwork.solve(base{:}, 'N', 1e5, 'xi_x', 1e-3, 'model', 'exact');
  assert(all(size(e.state) == [24 24]));
  disp('one policy at the Octave door');
end
