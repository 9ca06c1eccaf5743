% A friction law of the slip speed through the MEX: creepwork.solve with
% friction_law and its terms, friction_speed 'global' with Spiryagin's
% reduction, and 'polach', [mu0 A B], against the creepwork program on the
% same inputs (== on doubles: the C ABI's bits through both doors),
% CONTACT's tractcurv series 4 at 2 % (tests/data/contact_tractcurv.csv:
% Fx/(mu_s N) = -0.8444, printed to 4 digits) and Polach's full-sliding
% closed form A + (1 - A) exp(-B xi V) within 2e-4; the exact model with
% friction memory the CLI's bits, with its Jacobian too; bad inputs name
% themselves.
function test_friction()
  cli = getenv('CREEPWORK_CLI');
  grid = struct('kind', 'uniform', 'nx', 48, 'ny', 44, 'box_scale', 1.1);
  base = {'a', 6.304e-3, 'b', 12.61e-3, 'N', 106.7e3, 'exact_load', 1, 'V', 10, 'grid', grid};
  cli_base = ['--a 6.304e-3 --b 12.61e-3 --N 106700 --exact-load --V 10 --grid uniform ' ...
              '--nx 48 --ny 44 --box-scale 1.1 --format json'];
  law = {'friction_law', 'exponential', 'mu', 0.1368, 'mu_e1', 0.2232, 's_h1', 0.99};
  cli_law = '--friction-law exponential --mu 0.1368 --mu-e1 0.2232 --s-h1 0.99';

  % The global slip speed (full mode), series 4 at 2 %.
  r = creepwork.solve(base{:}, law{:}, 'xi_x', 0.02, 'friction_speed', 'global', ...
                      'k0', 0.54, 'alpha_inf', 0.02, 'beta', 0.62);
  same_as_cli(r, sprintf('%s %s --xi-x 0.02 --friction-speed global --k0 0.54 --alpha-inf 0.02 --beta 0.62', ...
                         cli_base, cli_law), cli);
  assert(abs(r.Fx / (0.36 * 106.7e3) - (-0.8444)) <= 0.5e-4 + 6e-5, sprintf('series 4: %.6f', ...
         r.Fx / (0.36 * 106.7e3)));
  % The law at every element, and Polach's law in full sliding.
  r = creepwork.solve(base{:}, law{:}, 'xi_x', 0.004);
  same_as_cli(r, sprintf('%s %s --xi-x 0.004', cli_base, cli_law), cli);
  r = creepwork.solve(base{:}, 'polach', [0.36 0.38 0.7], 'xi_x', 0.15);
  same_as_cli(r, sprintf('%s --polach 0.36,0.38,0.7 --xi-x 0.15', cli_base), cli);
  assert(abs(-r.Fx / (0.36 * 106.7e3) - (0.38 + 0.62 * exp(-0.7 * 0.15 * 10))) <= 2e-4);
  assert(abs(r.mu_static - 0.36) <= 1e-15);

  % Friction memory reaches the exact model: CONTACT's MEMDST 3 um, MEM_S0
  % 1 mm/s (tests/data/contact_tractcurv_memory.csv), the CLI's bits.
  memory = {'model', 'exact', 'friction_law', 'exponential', 'mu', 0.14, 'mu_e1', 0.19, 's_h1', 1.25, ...
            'memory_distance', 3e-6, 'memory_s0', 1e-3};
  r = creepwork.solve(base{:}, memory{:}, 'xi_x', 0.004);
  same_as_cli(r, sprintf(['%s --model exact --friction-law exponential --mu 0.14 --mu-e1 0.19 ' ...
                          '--s-h1 1.25 --memory-distance 3e-6 --memory-s0 1e-3 --xi-x 0.004'], ...
                         cli_base), cli);
  r = creepwork.jacobian(base{:}, memory{:}, 'xi_x', 0.004);
  [status, out] = system(sprintf(['%s solve %s --model exact --friction-law exponential ' ...
                                  '--mu 0.14 --mu-e1 0.19 --s-h1 1.25 --memory-distance 3e-6 ' ...
                                  '--memory-s0 1e-3 --xi-x 0.004 --jacobian 2>/dev/null'], ...
                                 cli, cli_base));
  assert(status == 0, out);
  t = regexp(out, '"jacobian": \{\s*"Fx": \{\s*"xi_x": (-?[0-9][-+.eE0-9]*)', 'tokens', 'once');
  assert(r.jacobian(1, 1) == str2double(t{1}), sprintf('dFx/dxi_x: %.17g (MEX) vs %s (CLI)', ...
         r.jacobian(1, 1), t{1}));

  ok = {'a', 7e-3, 'b', 5e-3, 'N', 100e3, 'xi_x', 1e-3, 'fields', false};
  expect_error(@() creepwork.solve(ok{:}, law{:}), 'creepwork:CW_ERR_INVALID_INPUT', '\<V = 0');
  expect_error(@() creepwork.solve(ok{:}, 'V', 10, 'polach', [0.36 1.5 0.7]), ...
               'creepwork:CW_ERR_INVALID_INPUT', 'polach_A');
  expect_error(@() creepwork.solve(ok{:}, 'V', 10, 'friction_law', 'stribeck'), ...
               'creepwork:CW_ERR_UNKNOWN_OPTION', 'stribeck');
  expect_error(@() creepwork.solve(ok{:}, 'V', 10, law{:}, 's_h1', 0), ...
               'creepwork:CW_ERR_INVALID_INPUT', '\<s_h1 = 0');
  disp('friction laws through the MEX');
end

function same_as_cli(r, args, cli)
  [status, out] = system(sprintf('%s solve %s 2>/dev/null', cli, args));
  assert(status == 0, out);
  pairs = regexp(out, '\n  "(\w+)": (-?[0-9][-+.eE0-9]*)', 'tokens');
  compared = 0;
  for k = 1:numel(pairs)
    name = pairs{k}{1};
    if isfield(r, name)
      v = str2double(pairs{k}{2});
      assert(r.(name) == v, sprintf('%s: %.17g (MEX) vs %.17g (CLI)', name, r.(name), v));
      compared = compared + 1;
    end
  end
  assert(compared >= 25, sprintf('compared %d numbers', compared));
end
