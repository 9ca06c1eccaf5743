% creepwork.solve against the creepwork program (programs/cli) on the same
% inputs: every number of cw_result that `creepwork solve --format json`
% prints equals the MEX's (== on doubles), for FASTSIM, the calibrated and
% the exact model (each with the CLI's default grid), through
% creepwork.solve and creepwork.solve_many (the model by name), and the fields of
% fields.csv (`creepwork solve --out DIR`) equal R.fields element by element.
cli = getenv('CREEPWORK_CLI');
base = {'a', 7e-3, 'b', 5e-3, 'N', 100e3, 'xi_x', 1e-3, 'xi_y', 5e-4, 'phi', 0.5};
cli_base = '--a 0.007 --b 0.005 --N 100000 --xi-x 0.001 --xi-y 0.0005 --spin 0.5';
models = {'fastsim', 'calibrated', 'exact'};
for m = 1:numel(models)
  [status, out] = system(sprintf('%s solve %s --model %s --format json 2>/dev/null', cli, ...
                                 cli_base, models{m}));
  assert(status == 0, out);
  % The top-level numbers of the JSON, read with str2double (strtod: correctly
  % rounded; jsondecode's parser is not, in the last bit).
  pairs = regexp(out, '\n  "(\w+)": (-?[0-9][-+.eE0-9]*)', 'tokens');
  r = creepwork.solve(base{:}, 'model', models{m});
  % solve_many with the model's name: one contact (the name is one value,
  % not one contact per character), the same numbers.
  many = creepwork.solve_many(base{:}, 'model', models{m}, 'full', true);
  assert(numel(many.Fx) == 1, sprintf('%s: %d contacts', models{m}, numel(many.Fx)));
  compared = 0;
  for k = 1:numel(pairs)
    name = pairs{k}{1};
    v = str2double(pairs{k}{2});
    if isfield(r, name)
      assert(r.(name) == v, sprintf('%s %s: %.17g (MEX) vs %.17g (CLI)', models{m}, name, ...
                                    r.(name), v));
      assert(many.(name) == v, sprintf('%s %s: %.17g (solve_many) vs %.17g (CLI)', ...
                                       models{m}, name, many.(name), v));
      compared = compared + 1;
    end
  end
  assert(compared >= 25, sprintf('%s: compared %d numbers', models{m}, compared));

  dir = tempname();
  [status, out] = system(sprintf('%s solve %s --model %s --out %s --no-plots 2>/dev/null', ...
                                 cli, cli_base, models{m}, dir));
  assert(status == 0, out);
  csv = dlmread(fullfile(dir, 'fields.csv'), ',', 1, 0);
  [nx, ny] = size(r.state);
  assert(rows(csv) == nx * ny);
  % columns i,j,x,y,area,state,pz,px,py,sx,sy,mz,work_paper,work_consistent
  names = {'x', 'y', 'area', '', 'pz', 'px', 'py', 'sx', 'sy', 'mz', 'work_paper', ...
           'work_consistent'};
  index = csv(:, 1) + 1 + nx * csv(:, 2);  % column-major (i+1, j+1)
  assert(isequal(r.state(index), csv(:, 6)));
  for c = 1:numel(names)
    if isempty(names{c}), continue; end
    field = r.fields.(names{c});
    assert(isequal(field(index), csv(:, c + 2)), sprintf('%s: field %s', models{m}, names{c}));
  end
  confirm_recursive_rmdir(false, 'local');
  rmdir(dir, 's');
end
disp('MEX totals and fields equal the CLI''s for fastsim, calibrated and exact');
