% creepwork.Transient on CONTACT's catt_to_cart (a sphere, h = 2.963 (x^2 +
% y^2) [m], on 34 x 33 cells of 0.25 mm from -4 mm; N = 0.4705 N, G = 1e6,
% nu = 0.28, mu = 0.4013): the Cattaneo shift to Fx = -0.657 mu N and 14
% rolling steps equal `creepwork transient` on the same gap and steps (the C
% API's bits: the program prints every number round-trip) and CONTACT's
% printed creepages and element counts (tests/data/transient/catt_to_cart.csv,
% eve70a/CONTACT d431cdb); a trial repeated after rewind and after restore
% gives the same bits; the traction sums to Fx; errors name their input.
% The shift and two steps world-fixed equal `creepwork transient
% --coordinates world` bitwise; the work field sums to W_step (1e-12); the
% Jacobian at prescribed Fx (d xi_x / d Fx) equals a central difference of
% two trials (h = 1e-5 mu N) to 1e-6; each step's USFD wear (its mild
% regime) is k1 W_step (1e-12) and the map sums to the total.
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
cli = transient_cli_rows(out, n_steps);
f = fopen(fullfile(dir, 'steps3.csv'), 'w');
fprintf(f, 'dq_m,Fx\n0,%.17g\n%.17g,%.17g\n%.17g,%.17g\n', Fx, dx, Fx, dx, Fx);
fclose(f);
[status, out] = system(sprintf(['%s transient --steps %s --gap %s --prescribe forces ' ...
                                '--coordinates world ' ...
                                '--N 0.4705 --G 1e6 --nu 0.28 --mu 0.4013 2>/dev/null'], ...
                               getenv('CREEPWORK_CLI'), fullfile(dir, 'steps3.csv'), ...
                               fullfile(dir, 'gap.csv')));
assert(status == 0, out);
cli_world = transient_cli_rows(out, 3);
confirm_recursive_rmdir(false, 'local');
rmdir(dir, 's');

fid = fopen(fullfile(getenv('CREEPWORK_TEST_DATA_DIR'), 'transient', 'catt_to_cart.csv'));
ref = textscan(fid, '%d %s %s %d %d %f', 'Delimiter', ',', 'HeaderLines', 1);
fclose(fid);

warning('off', 'creepwork:implausibleUnits');  % CONTACT's example: a 0.47 N load
t = creepwork.Transient(grid, contact{:});
assert(t.nx == nx && t.ny == ny);
names = {'xi_x', 'xi_y', 'phi', 'Fx', 'Fy', 'Mz', 'n_adhesion', 'n_slip', 'W_step', 'W_slip'};
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

% World-fixed coordinates: the CLI's bits.
w = creepwork.Transient(grid, contact{:});
expect_error(@() w.set_coordinates('ground'), 'creepwork:badValue', 'coordinates');
expect_error(@() w.set_coordinates(7), 'creepwork:CW_ERR_UNKNOWN_OPTION', 'coordinates');
w.set_coordinates('world');
for k = 1:3
  r = w.step('dq', (k > 1) * dx, 'Fx', Fx);
  w.commit();
  for c = 1:numel(names)
    assert(r.(names{c}) == cli_world(k, c + 3), sprintf('world step %d %s', k, names{c}));
  end
end
delete(w);

% The work field, the Jacobian and wear over steps.
t.start_zero();
expect_error(@() t.jacobian(), 'creepwork:CW_ERR_NO_SOLUTION', '.');
k1 = 5.3e-9;  % cw_wear_params_init's usfd_k1
total = 0;
for k = 1:4
  r = t.step('dq', (k > 1) * dx, 'Fx', Fx);
  t.commit();
  m = t.add_wear();
  if k == 1
    assert(m == 0);
  else
    assert(abs(m / (k1 * r.W_step) - 1) <= 1e-12, sprintf('step %d wear', k));
  end
  total = total + m;
end
ww = t.wear();
assert(abs(ww.mass / total - 1) <= 1e-12 && abs(sum(ww.mass_map(:)) / total - 1) <= 1e-12);
assert(all(size(ww.mass_map) == [nx, ny]));
expect_error(@() t.add_wear('law', 9), 'creepwork:CW_ERR_UNKNOWN_OPTION', 'law');
t.reset_wear();
assert(t.wear().mass == 0);
r = t.step('dq', dx, 'Fx', -0.5 * mu * load);
fw = t.fields();
assert(abs(sum(fw.work(:)) / r.W_step - 1) <= 1e-12);
J = t.jacobian();
assert(all(size(J) == [3, 3]));
hF = 1e-5 * mu * load;
side = zeros(1, 2);
for k = 1:2
  q = t.step('dq', dx, 'Fx', -0.5 * mu * load + (3 - 2 * k) * hF);
  side(k) = q.xi_x;
  t.rewind();
end
fd = (side(1) - side(2)) / (2 * hF);
assert(abs(fd / J(1, 1) - 1) <= 1e-6, sprintf('d xi_x / d Fx: %.9e vs %.9e', J(1, 1), fd));

% FASTSIM's transient form refuses what is the exact model's.
s = creepwork.Transient(grid, contact{:}, 'model', 'fastsim');
expect_error(@() s.set_coordinates('world'), 'creepwork:CW_ERR_INVALID_INPUT', 'CW_MODEL_FASTSIM');
s.step('dq', 0, 'Fx', Fx);
expect_error(@() s.jacobian(), 'creepwork:CW_ERR_INVALID_INPUT', 'CW_MODEL_FASTSIM');
delete(s);

delete(t);
expect_error(@() t.step('dq', dx, 'xi_x', 1e-3), 'creepwork:badHandle', 'no such creepwork transient');
disp('creepwork.Transient: the CLI''s bits and CONTACT''s digits on catt_to_cart');

