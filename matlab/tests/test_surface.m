% Solver.temperature and Solver.damage: both bodies' temperatures are nx-by-ny
% and share one value in contact, T_c = (b1 T0_1 + b2 T0_2)/(b1 + b2), the
% maxima are the largest contact values, the power is V times the work
% map's sum, the solve's rolling direction is passed on; in full sliding
% the RCF index is max(-0.5, mu - k/pz) and the T_gamma density sums (x
% area) to W_macro; errors carry the library's identifier and name the input.
grid = struct('kind', 'uniform', 'nx', 24, 'ny', 20, 'box_scale', 1.2);
s = creepwork.Solver(grid);
r = s.solve('a', 7e-3, 'b', 5e-3, 'N', 100e3, 'xi_x', 1.5e-3, 'xi_y', -5e-4, 'phi', 0.5, ...
            'rolling_direction', -1);
t = s.temperature('rolling_speed', 30, 'T0_1', 10, 'T0_2', 70, 'conductivity_2', 200);
assert(isequal(size(t.rail), [24, 20]) && isequal(size(t.wheel), [24, 20]));
inside = r.state >= 1;
b1 = sqrt(50 * 7850 * 450);
b2 = sqrt(200 * 7850 * 450);
assert(abs(t.contact_temperature - (b1 * 10 + b2 * 70) / (b1 + b2)) <= 1e-12);
assert(isequal(t.rail(inside), t.wheel(inside)));
assert(t.T_max_1 == max(t.rail(inside)) && t.T_max_2 == max(t.wheel(inside)));
assert(abs(t.power - 30 * r.W_consistent) <= 1e-12 * t.power);
assert(t.x_max_1 > 0);  % rolling towards -x: the hottest contact element on the high-x side
d = s.solve('a', 7e-3, 'b', 5e-3, 'N', 100e3, 'mu', 0.3, 'xi_x', 0.05);
assert(d.n_adhesion == 0);
k = s.damage('k_yield', 200e6);
expect = -0.5 * ones(24, 20);
on = d.state >= 1 & d.fields.pz > 0;
expect(on) = max(-0.5, 0.3 - 200e6 ./ d.fields.pz(on));
assert(max(abs(k.rcf_index(:) - expect(:))) <= 1e-12);
assert(abs(sum(k.t_gamma_density(:) .* d.fields.area(:)) - d.W_macro) <= 1e-12 * d.W_macro);
assert(k.T_gamma == d.W_macro);
try
  s.damage('k_yield', 0);
  error('test:noError', 'k_yield = 0 accepted');
catch err
  assert(strcmp(err.identifier, 'creepwork:CW_ERR_INVALID_INPUT'), err.identifier);
  assert(~isempty(strfind(err.message, 'k_yield')), err.message);
end
try
  s.temperature('rolling_speed', 30, 'conductivity_1', -1);
  error('test:noError', 'conductivity_1 < 0 accepted');
catch err
  assert(strcmp(err.identifier, 'creepwork:CW_ERR_INVALID_INPUT'), err.identifier);
  assert(~isempty(strfind(err.message, 'conductivity_1')), err.message);
end
% The library's plausibility rules (header, cw_temperature_params_check and
% cw_damage_params_check): just beyond a threshold its message, just inside none.
implausible = ' is implausible for a wheel-rail contact: ';
tf = @(varargin) s.temperature(varargin{:});
df = @(varargin) s.damage(varargin{:});
cases = {{tf, {'rolling_speed', 30, 'conductivity_1', 0.05}, ...
          ['conductivity_1 = 0.05 W/(m K)', implausible], 'W/(mm K) typed as W/(m K)?'}, ...
         {tf, {'rolling_speed', 30, 'density_2', 7.85}, ...
          ['density_2 = 7.85 kg/m^3', implausible], 'g/cm^3'}, ...
         {tf, {'rolling_speed', 150.5}, ...
          ['rolling_speed = 150.5 m/s', implausible], 'km/h typed as m/s?'}, ...
         {df, {'k_yield', 300}, ['k_yield = 300 Pa', implausible], 'MPa or N/mm^2 typed as Pa?'}, ...
         {df, {'k_yield', 3e8, 'wlrm_onset', 0, 'wlrm_peak', 0.065}, ...
          ['wlrm_peak = 0.065 N', implausible], 'kN or J/mm typed as N?'}};
for k = 1:numel(cases)
  c = cases{k};
  lastwarn('');
  c{1}(c{2}{:});
  [msg, id] = lastwarn();
  assert(strcmp(id, 'creepwork:implausibleUnits') && ~isempty(strfind(msg, c{3})) && ...
         ~isempty(strfind(msg, c{4})), msg);
end
lastwarn('');
s.temperature('rolling_speed', 149.5, 'conductivity_1', 1.01);
s.damage('k_yield', 1.01e6);
assert(isempty(lastwarn()), lastwarn());
delete(s);
% Friction mu(T): CONTACT's euro_tractcurv at 25 % creepage (L=6, -0.19 over
% 400 deg C; Fx/(0.33 N) = -0.6108, T_max 364.7 deg C printed) within the C
% test's tolerances; unsorted points named.
e = creepwork.Solver(struct('kind', 'uniform', 'nx', 44, 'ny', 44, 'box_scale', 1.1));
tp = struct('T0_1', 0, 'T0_2', 0, 'discretisation', 'contact');
euro = {'model', 'exact', 'a', 6.304e-3, 'b', 12.61e-3, 'N', 106.7e3, 'V', 10, 'xi_x', 0.25};
[r, t] = e.solve_mu_T([0 0.33; 400 0.14], tp, euro{:});
assert(abs(r.Fx / (0.33 * 106.7e3) + 0.6108) <= 5.5e-4, sprintf('Fx %g', r.Fx));
assert(abs(max(t.T_max_1, t.T_max_2) - 364.7) <= 2e-3 * 364.7, sprintf('T_max %g', t.T_max_1));
assert(t.iterations > 2 && t.T_max_1 == max(t.rail(r.state >= 1)));
expect_error(@() e.solve_mu_T([400 0.33; 0 0.14], tp, euro{:}), 'creepwork:CW_ERR_INVALID_INPUT', ...
             'temperature\[1\]');
delete(e);
disp('temperature and damage indices as the header defines them');
