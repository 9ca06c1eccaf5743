% A contact of any shape: a gap grid (kind 'gap') and the gap as an
% nx-by-ny array (gap_len follows it). A Hertzian gap A x^2 + B y^2 on the
% uniform grid over 1.2 a x 1.2 b, a and b from Hertz's theory, is the
% problem the elliptic exact model solves there (header, CW_GRID_GAP): at
% tolerance 1e-12 both agree to 1e-8 mu N, and so do their Jacobians'
% creepage columns to 1e-8 of each row's scale (the N columns differ by
% design: the gap is held there, a and b here; doc/theory/non-hertzian.md).
% Two separate lobes are two patches whose forces add up to the totals
% (cw_solver_get_patches). N = 0 has no Jacobian: an error naming it as typed.
N = 60e3;
creep = {'xi_x', 4e-4, 'xi_y', -3e-4, 'phi', 0.3, 'model', 'exact', 'tolerance', 1e-12, ...
         'warm_start', 0, 'N', N};
A = 1 / (2 * 0.46);
B = 1 / (2 * 0.30);
hz = creepwork.hertz(A, B, N, 82e9 / (1 - 0.28));
n = 24;
S = 1.2;
grid = struct('kind', 'gap', 'nx', n, 'ny', n, 'x0', -S * hz.a + S * hz.a / n, ...
              'y0', -S * hz.b + S * hz.b / n, 'dx', 2 * S * hz.a / n, 'dy', 2 * S * hz.b / n);
[x, y] = ndgrid(grid.x0 + grid.dx * (0:n - 1), grid.y0 + grid.dy * (0:n - 1));
g = creepwork.solve(creep{:}, 'gap', A * x.^2 + B * y.^2, 'grid', grid);
e = creepwork.solve(creep{:}, 'a', hz.a, 'b', hz.b, ...
                    'grid', struct('kind', 'uniform', 'nx', n, 'ny', n, 'box_scale', S));
muN = 0.3 * N;
assert(abs(g.Fx - e.Fx) <= 1e-8 * muN && abs(g.Fy - e.Fy) <= 1e-8 * muN);
assert(abs(g.Mz - e.Mz) <= 1e-8 * muN * hz.a);
assert(g.n_contact == e.n_contact && g.n_slip == e.n_slip && g.n_patches == 1);
assert(numel(e.patches.Fx) == 1 && e.patches.Fx == e.Fx);
jg = creepwork.jacobian(creep{:}, 'gap', A * x.^2 + B * y.^2, 'grid', grid);
je = creepwork.jacobian(creep{:}, 'a', hz.a, 'b', hz.b, ...
                        'grid', struct('kind', 'uniform', 'nx', n, 'ny', n, 'box_scale', S));
scale = [1e-3, 1e-3, 1e-3 / sqrt(hz.a * hz.b), N];
for row = 1:4
  row_scale = sum(abs(je.jacobian(row, :)) .* scale);
  assert(all(abs(jg.jacobian(row, 1:3) - je.jacobian(row, 1:3)) .* scale(1:3) <= 1e-8 * row_scale));
end
try
  creepwork.jacobian(creep{:}, 'gap', A * x.^2 + B * y.^2, 'grid', grid, 'N', 0);
  error('test:noError', 'a Jacobian at normal_force = 0 was accepted');
catch err
  assert(strncmp(err.message, 'N = 0: ', 7), err.message);  % the load as typed
end
% Two lobes 12 mm apart across.
grid = struct('kind', 'gap', 'nx', 30, 'ny', 56, 'x0', -5e-3, 'y0', -12e-3, ...
              'dx', 0.35e-3, 'dy', 0.45e-3);
[x, y] = ndgrid(grid.x0 + grid.dx * (0:29), grid.y0 + grid.dy * (0:55));
h = min(x.^2 / 0.9 + (y + 6e-3).^2 / 0.5, x.^2 / 0.9 + (y - 6e-3).^2 / 0.5 + 2e-6);
s = creepwork.Solver(grid);
r = s.solve(creep{:}, 'gap', h);
p = r.patches;
assert(r.n_patches == 2 && numel(p.Fn) == 2 && p.y_centroid(1) < 0 && p.y_centroid(2) > 0);
assert(abs(sum(p.Fn) - N) <= 1e-9 * N);
assert(abs(sum(p.Fx) - r.Fx) <= 1e-9 * muN && abs(sum(p.Fy) - r.Fy) <= 1e-9 * muN);
assert(sum(p.n_contact) == r.n_contact);
% Another model on a gap grid: the library's error, naming the model.
try
  s.solve(creep{:}, 'gap', h, 'model', 'calibrated');
  error('test:noError', 'calibrated on a gap grid was accepted');
catch err
  assert(~isempty(strfind(err.message, 'model = calibrated')), err.message);
end
delete(s);
disp('gap grids: the elliptic exact model, patches adding up to the totals');
