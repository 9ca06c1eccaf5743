% Implausible units warn (identifier creepwork:implausibleUnits) exactly
% where the creepwork CLI warns: each rule just beyond and just inside its
% threshold, through creepwork.solve and the CLI.
cli = getenv('CREEPWORK_CLI');
base = struct('a', 7e-3, 'b', 5e-3, 'N', 100e3);
given = {'flexibility', 'given', 'L1', 5e-14, 'L2', 5e-14, 'L3', 5e-14};
% parameter, CLI option, beyond, inside, extra parameters
rules = {'a', 'a', 0.11, 0.09, {'b', 0.08}; 'a', 'a', 0.9e-4, 1.1e-4, {};
         'b', 'b', 0.11, 0.09, {'a', 0.08}; 'b', 'b', 0.9e-4, 1.1e-4, {};
         'N', 'N', 1.1e7, 0.9e7, {}; 'N', 'N', 999, 1001, {}; 'mu', 'mu', 1.6, 1.4, {};
         'G', 'G', 0.9e6, 1.1e6, {}; 'G', 'G', 1.1e12, 0.9e12, {};
         'L1', 'L1', 2e-10, 0.9e-10, given; 'L2', 'L2', 0.9e-18, 1.1e-18, given;
         'L3', 'L3', 2e-10, 0.9e-10, given; 'xi_x', 'xi-x', -0.6, -0.4, {};
         'xi_y', 'xi-y', 0.6, 0.4, {}; 'phi', 'spin', 51, 49, {}};
for k = 1:rows(rules)
  for value = [rules{k, 3}, rules{k, 4}]
    p = base;
    extra = rules{k, 5};
    for e = 1:2:numel(extra), p.(extra{e}) = extra{e + 1}; end
    p.(rules{k, 1}) = value;
    lastwarn('', '');
    creepwork.solve(p, 'fields', false);
    [msg, id] = lastwarn();
    mine = strcmp(id, 'creepwork:implausibleUnits');
    args = '';
    names = fieldnames(p);
    option = struct('a', 'a', 'b', 'b', 'N', 'N', 'mu', 'mu', 'G', 'G', 'L1', 'L1', 'L2', 'L2', ...
                    'L3', 'L3', 'xi_x', 'xi-x', 'xi_y', 'xi-y', 'phi', 'spin');
    for n = 1:numel(names)
      if ~strcmp(names{n}, 'flexibility')
        args = [args, sprintf(' --%s %.17g', option.(names{n}), p.(names{n}))];
      end
    end
    [status, err] = system(sprintf('%s solve%s 2>&1 >/dev/null', cli, args));
    assert(status == 0, err);
    theirs = ~isempty(strfind(err, 'implausible'));
    assert(mine == theirs && mine == (value == rules{k, 3}), ...
           sprintf('%s = %g: MEX %d, CLI %d (%s)', rules{k, 1}, value, mine, theirs, msg));
    if mine  % (Octave puts "creepwork_mex: " before a MEX's message)
      assert(~isempty(regexp(msg, ['(^|: )', rules{k, 1}, ' = '], 'once')), msg);
    end
  end
end
disp('unit warnings where the CLI warns');
