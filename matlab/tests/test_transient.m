% creepwork.Transient on CONTACT's catt_to_cart (a sphere, h = 2.963 (x^2 +
% y^2) [m], on 34 x 33 cells of 0.25 mm from -4 mm; N = 0.4705 N, G = 1e6,
% nu = 0.28, mu = 0.4013): the Cattaneo shift to Fx = -0.657 mu N and 14
% rolling steps equal `creepwork transient` on the same gap and steps (the C
% API's bits: the program prints every number round-trip) and CONTACT's
% printed creepages and element counts (tests/data/transient/catt_to_cart.csv,
% eve70a/CONTACT d431cdb); a trial repeated after rewind and after restore
% gives the same bits; the traction sums to Fx; errors name their input.
nx = 34; ny = 33; dx = 0.25e-3; x0 = -4e-3;
mu = 0.4013; load = 0.4705; Fx = -0.657 * mu * load;
grid = struct('kind', 'gap', 'nx', nx, 'ny', ny, 'x0', x0, 'y0', x0, 'dx', dx, 'dy', dx);
[x, y] = ndgrid(x0 + dx * (0:nx - 1), x0 + dx * (0:ny - 1));
h = 2.963 * (x .* x + y .* y);
contact = {'gap', h, 'N', load, 'G', 1e6, 'nu', 0.28, 'mu', mu};
n_steps = 15;

% The command-line program on the same gap and steps.
dir = tempname();
mkdir(dir);
f = fopen(fullfile(dir, 'gap.csv'), 'w');
fprintf(f, 'x_m,y_m,h_m\n');
fprintf(f, '%.17g,%.17g,%.17g\n', [x(:), y(:), h(:)].');
fclose(f);
f = fopen(fullfile(dir, 'steps.csv'), 'w');
fprintf(f, 'dq_m,Fx\n0,%.17g\n', Fx);
fprintf(f, '%.17g,%.17g\n', repmat([dx; Fx], 1, n_steps - 1));
fclose(f);
[status, out] = system(sprintf(['%s transient --steps %s --gap %s --prescribe forces ' ...
                                '--N 0.4705 --G 1e6 --nu 0.28 --mu 0.4013 2>/dev/null'], ...
                               getenv('CREEPWORK_CLI'), fullfile(dir, 'steps.csv'), ...
                               fullfile(dir, 'gap.csv')));
assert(status == 0, out);
lines = strsplit(strtrim(out), "\n");
lines = lines(~strncmp(lines, '#', 1));
assert(numel(lines) == n_steps, sprintf('%d lines from the CLI', numel(lines)));
% columns: step line dq_m xi_x xi_y phi Fx Fy Mz n_adhesion n_slip W_step
cli = zeros(n_steps, 12);
for k = 1:n_steps
  cli(k, :) = str2double(strsplit(strtrim(lines{k})));  % strtod: correctly rounded
end
confirm_recursive_rmdir(false, 'local');
rmdir(dir, 's');

fid = fopen(fullfile(getenv('CREEPWORK_TEST_DATA_DIR'), 'transient', 'catt_to_cart.csv'));
ref = textscan(fid, '%d %s %s %d %d %f', 'Delimiter', ',', 'HeaderLines', 1);
fclose(fid);

warning('off', 'creepwork:implausibleUnits');  % CONTACT's example: a 0.47 N load
t = creepwork.Transient(grid, contact{:});
assert(t.nx == nx && t.ny == ny);
names = {'xi_x', 'xi_y', 'phi', 'Fx', 'Fy', 'Mz', 'n_adhesion', 'n_slip', 'W_step'};
for k = 1:n_steps
  r = t.step('dq', (k > 1) * dx, 'Fx', Fx);
  t.commit();
  for c = 1:numel(names)
    assert(r.(names{c}) == cli(k, c + 3), sprintf('step %d %s: %.17g (MEX) vs %.17g (CLI)', ...
                                                   k, names{c}, r.(names{c}), cli(k, c + 3)));
  end
  value = r.xi_x * (1 + 999 * (k == 1));  % CONTACT prints the shift in mm
  assert(strcmp(sprintf('%.3E', value), ref{3}{k}), sprintf('case %d: %.3E vs CONTACT %s', ...
                                                           k, value, ref{3}{k}));
  assert(r.n_adhesion == ref{4}(k) && r.n_slip == ref{5}(k), sprintf('case %d counts', k));
  assert(r.steps_committed == k - 1);
end

% A trial after rewind and after restore: the same bits; the traction sums to Fx.
saved = t.save();
assert(isa(saved, 'uint64') && numel(saved) > nx * ny);
a = t.step('dq', dx, 'Fx', -0.5 * mu * load);
fa = t.fields();
t.rewind();
t.step('dq', dx, 'xi_x', 1e-3);
t.rewind();
b = t.step('dq', dx, 'Fx', -0.5 * mu * load);
assert(isequal(a, b));
t.commit();
t.step('dq', dx, 'Fx', -0.5 * mu * load);
t.commit();
t.restore(saved);
expect_error(@() t.commit(), 'creepwork:CW_ERR_NO_SOLUTION', 'no step to commit');
c = t.step('dq', dx, 'Fx', -0.5 * mu * load);
assert(isequal(a, c));
fc = t.fields();
assert(isequal(fa, fc));
assert(abs(sum(fa.px(:)) * dx * dx - a.Fx) <= 1e-12 * abs(a.Fx));
assert(sum(fa.state(:) == 1) == a.n_adhesion && sum(fa.state(:) == 2) == a.n_slip);
assert(all(size(fa.px) == [nx, ny]));
assert(max(abs(fa.x(:) - x(:))) <= 1e-15 && max(abs(fa.y(:) - y(:))) <= 1e-15);  % centres, nx-by-ny

% Errors name their input.
expect_error(@() t.step('dq', 2 * dx, 'xi_x', 1e-3), 'creepwork:CW_ERR_INVALID_INPUT', 'dq');
expect_error(@() t.step('dq', dx, 'Fx', -mu * load), 'creepwork:CW_ERR_INVALID_INPUT', 'mu N');
expect_error(@() t.step('dq', dx, 'Fy', 0.01), 'creepwork:usage', '^Fy: needs Fx');
expect_error(@() t.step('dq', dx, 'xi', 1e-3), 'creepwork:unknownField', ...
             '''xi'' is not a field of cw_transient_input');
expect_error(@() t.restore(double(saved)), 'creepwork:badValue', '^state must be the uint64');
expect_error(@() t.restore(saved(1:3)), 'creepwork:CW_ERR_INVALID_INPUT', '.');
expect_error(@() creepwork.Transient(grid, contact{:}, 'model', 'calibrated'), ...
             'creepwork:CW_ERR_INVALID_INPUT', 'model');
expect_error(@() creepwork.Transient(grid, 'gap', h, 'G', 1e6, 'mu', mu), ...
             'creepwork:missingInput', '^N: missing');
expect_error(@() creepwork.Transient(grid, contact{:}, 'gap', h.'), ...
             'creepwork:CW_ERR_INVALID_INPUT', 'transposed');
delete(t);
expect_error(@() t.step('dq', dx, 'xi_x', 1e-3), 'creepwork:badHandle', 'no such creepwork transient');
disp('creepwork.Transient: the CLI''s bits and CONTACT''s digits on catt_to_cart');
