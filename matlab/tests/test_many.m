% solve_many: one cw_batch_solve call; its totals equal creepwork.solve one
% by one (==), and a bad contact among 2000 gets its status and message
% while the others are solved.
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
disp('solve_many equals solve one by one; the bad contact is reported alone');
