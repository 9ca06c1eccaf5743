% solve_many: one cw_batch_solve call; its totals equal creepwork.solve one
% by one (==), a bad contact among 2000 gets its status and message while
% the others are solved, and an enumeration's name is one value for all.
n = 2000;
bad = 1234;
xi_x = linspace(-3e-3, 3e-3, n);
nu = 0.28 * ones(1, n);
nu(bad) = 0.6;
r = creepwork.solve_many('a', 7e-3, 'b', 5e-3, 'N', 100e3, 'xi_x', xi_x, 'xi_y', 1e-3, ...
                         'phi', 0.4, 'nu', nu);
assert(isequal(size(r.Fx), [1, n]) && isequal(size(r.status), [1, n]));
c = creepwork.constants();
assert(r.status(bad) == c.CW_ERR_INVALID_INPUT && nnz(r.status) == 1);
assert(~isempty(regexp(r.message{bad}, '\<nu\>', 'once')), r.message{bad});
assert(isempty(r.message{1}) && isnan(r.Fx(bad)));
for k = [1, bad - 1, bad + 1, n]
  one = creepwork.solve('a', 7e-3, 'b', 5e-3, 'N', 100e3, 'xi_x', xi_x(k), 'xi_y', 1e-3, ...
                        'phi', 0.4, 'fields', false);
  assert(r.Fx(k) == one.Fx && r.Fy(k) == one.Fy && r.Mz(k) == one.Mz && ...
         r.W_macro(k) == one.W_macro, sprintf('contact %d', k));
end
% Threads do not change a bit; a column input gives column outputs.
r1 = creepwork.solve_many('a', 7e-3, 'b', 5e-3, 'N', 100e3, 'xi_y', xi_x', 'threads', 1);
r2 = creepwork.solve_many('a', 7e-3, 'b', 5e-3, 'N', 100e3, 'xi_y', xi_x', 'threads', 2);
assert(isequal(size(r1.Fy), [n, 1]) && isequal(r1.Fy, r2.Fy) && isequal(r1.Mz, r2.Mz));
% An enumeration given as text is one value for every contact, never one
% contact per character: 'fastsim' (7 characters) with scalars is one
% contact, 'exact' (5) with three creepages three, each equal to the
% one-by-one solve (cold, as the batch solves the exact model).
one = creepwork.solve_many('a', 7e-3, 'b', 5e-3, 'N', 100e3, 'xi_x', 1e-3, 'model', 'fastsim');
ref = creepwork.solve('a', 7e-3, 'b', 5e-3, 'N', 100e3, 'xi_x', 1e-3, 'fields', false);
assert(isequal(size(one.Fx), [1, 1]) && one.status == 0 && one.model == c.CW_MODEL_FASTSIM);
assert(one.Fx == ref.Fx && one.Fy == ref.Fy && one.W_macro == ref.W_macro);
xi = [2e-4, 6e-4, 1.2e-3];
three = creepwork.solve_many('a', 7e-3, 'b', 5e-3, 'N', 100e3, 'xi_x', xi, 'model', 'exact');
assert(isequal(size(three.Fx), [1, 3]) && all(three.status == 0));
assert(all(three.model == c.CW_MODEL_EXACT));
for k = 1:3
  e = creepwork.solve('a', 7e-3, 'b', 5e-3, 'N', 100e3, 'xi_x', xi(k), 'model', 'exact', ...
                      'warm_start', 0, 'fields', false);
  assert(three.Fx(k) == e.Fx && three.Mz(k) == e.Mz, sprintf('exact contact %d', k));
end
% 'progress': a function handle sees the contacts done rise to the total
% (2000 contacts, 20 a part: 100 calls) and the results (the bad contact
% among them) equal one call's bit for bit; a bad value names the option.
function note_progress(done, total)  % defined before its use: a script
  global seen
  seen(end + 1, :) = [done, total];
end
global seen
seen = zeros(0, 2);
rp = creepwork.solve_many('a', 7e-3, 'b', 5e-3, 'N', 100e3, 'xi_x', xi_x, 'xi_y', 1e-3, ...
                          'phi', 0.4, 'nu', nu, 'progress', @(done, total) note_progress(done, total));
assert(rows(seen) == 100 && isequal(seen(end, :), [n, n]) && all(diff(seen(:, 1)) > 0));
assert(isequal(rp.status, r.status) && isequal(rp.message, r.message));
assert(isequal(rp.Fy(~rp.status), r.Fy(~r.status)) && isequal(rp.Mz(~rp.status), r.Mz(~r.status)));
assert(isequal(isnan(rp.Fx), isnan(r.Fx)));
try
  creepwork.solve_many('a', 7e-3, 'b', 5e-3, 'N', 100e3, 'xi_x', xi_x, 'progress', -1);
  error('no error for progress = -1');
catch err
  assert(strcmp(err.identifier, 'creepwork:badValue'), err.message);
  assert(~isempty(strfind(err.message, 'progress')), err.message);
end
% A progress function that fails stops the solve with its own error.
try
  creepwork.solve_many('a', 7e-3, 'b', 5e-3, 'N', 100e3, 'xi_x', xi_x, ...
                       'progress', @(done, total) error('user:stop', 'stopped at %d', done));
  error('no error from the progress function');
catch err
  assert(strcmp(err.identifier, 'user:stop') && strcmp(err.message, 'stopped at 20'), err.message);
end
disp('solve_many equals solve one by one; the bad contact is reported alone; progress');
