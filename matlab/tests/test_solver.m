% creepwork.Solver and the array layout: fields are nx-by-ny with x along
% the first index (on a 30 x 20 uniform grid over 1.2a x 1.2b the element
% centres are -1.2a + (i + 1/2) dx); the fields sum to the totals as the
% header defines them; the Jacobian's totals equal the solve's.
base = {'a', 7e-3, 'b', 5e-3, 'N', 100e3, 'xi_x', 1e-3, 'xi_y', 5e-4, 'phi', 0.5};
grid = struct('kind', 'uniform', 'nx', 30, 'ny', 20, 'box_scale', 1.2);
s = creepwork.Solver(grid);
assert(s.nx == 30 && s.ny == 20);
r = s.solve(base{:});
assert(isequal(size(r.fields.pz), [30, 20]) && isequal(size(r.state), [30, 20]));
x = -1.2 * 7e-3 + ((0:29)' + 0.5) * (2.4 * 7e-3 / 30);
y = -1.2 * 5e-3 + ((0:19) + 0.5) * (2.4 * 5e-3 / 20);
assert(max(max(abs(r.fields.x - repmat(x, 1, 20)))) < 1e-15);
assert(max(max(abs(r.fields.y - repmat(y, 30, 1)))) < 1e-15);
f = r.fields;
assert(abs(sum(f.px(:) .* f.area(:)) - r.Fx) <= 1e-12 * (abs(r.Fx) + abs(r.Fy)));
assert(abs(sum(f.mz(:)) - r.Mz) <= 1e-12 * abs(r.Mz));
assert(abs(sum(f.work_consistent(:)) - r.W_consistent) <= 1e-12 * r.W_consistent);
assert(nnz(r.state == 2) == r.n_slip && numel(r.profile.y) == 20);
j = s.jacobian(base{:});
assert(isequal(size(j.jacobian), [4, 4]) && j.Fx == r.Fx && j.Mz == r.Mz);
assert(j.jacobian(1, 1) < 0 && j.jacobian(2, 2) < 0);  % dFx/dxi_x, dFy/dxi_y oppose the creepage
% Warm starts of the exact model agree with cold ones to the tolerance.
e = creepwork.Solver(struct('kind', 'uniform', 'nx', 24, 'ny', 24, 'box_scale', 1.2));
for xi = [1e-3, 1.1e-3]
  warm = e.solve(base{:}, 'xi_x', xi, 'model', 'exact', 'tolerance', 1e-10, 'fields', false);
  cold = creepwork.solve(base{:}, 'xi_x', xi, 'model', 'exact', 'tolerance', 1e-10, ...
                         'warm_start', 0, 'fields', false);
  assert(abs(warm.Fx - cold.Fx) <= 1e-7 * (abs(cold.Fx) + abs(cold.Fy)));
end
delete(e);
delete(s);
p = creepwork.params();
assert(p.mu == 0.3 && p.G == 82e9 && p.nu == 0.28);
disp('Solver, layout and sums as the header defines them');
