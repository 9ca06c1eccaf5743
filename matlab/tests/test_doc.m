% The try/catch example of doc/octave.md runs and displays what its
% comments say (the quick start block is matlab/examples/quickstart.m: the
% doc recipe test checks that file and runs it).
text = fileread(fullfile(getenv('CREEPWORK_SOURCE_DIR'), 'doc', 'octave.md'));
blocks = regexp(text, '```matlab\n(.*?)```', 'tokens');
ran = 0;
for k = 1:numel(blocks)
  code = blocks{k}{1};
  if isempty(strfind(code, 'catch err'))
    continue;
  end
  expected = regexp(code, 'disp\([^)]*\)\s*% ([^\n]*)', 'tokens');
  out = strsplit(strtrim(evalc(code)), "\n");
  assert(numel(out) == numel(expected), sprintf('printed %d lines, %d expected', numel(out), ...
                                                numel(expected)));
  for e = 1:numel(expected)
    assert(strcmp(strtrim(out{e}), strtrim(expected{e}{1})), sprintf('printed "%s", doc says "%s"', ...
                                                                    out{e}, expected{e}{1}));
  end
  ran = ran + 1;
end
assert(ran == 1);
disp('the doc''s error example prints what it says');
