% The Octave quick start (matlab/examples/quickstart.m) prints exactly what
% the C quick start (examples/c_quickstart/quickstart.c) prints: the same
% contact, the same format, so the same digits.
[status, c_out] = system(getenv('CREEPWORK_C_QUICKSTART'));
assert(status == 0, 'the C quick start failed');
addpath(getenv('CREEPWORK_EXAMPLES'));
octave_out = evalc('quickstart');
disp(octave_out);
assert(strcmp(strtrim(octave_out), strtrim(c_out)), ...
       sprintf('Octave printed\n%s\nC printed\n%s', octave_out, c_out));
assert(numel(strsplit(strtrim(c_out), "\n")) == 3);
