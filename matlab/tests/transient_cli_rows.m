% ROWS = TRANSIENT_CLI_ROWS(OUT, N): the N text rows of `creepwork
% transient` (comments dropped) as numbers: step line dq_m xi_x xi_y phi Fx
% Fy Mz n_adhesion n_slip W_step W_slip, each printed round-trip.
function rows = transient_cli_rows(out, n)
  lines = strsplit(strtrim(out), "\n");
  lines = lines(~strncmp(lines, '#', 1));
  assert(numel(lines) == n, sprintf('%d lines from the CLI', numel(lines)));
  rows = zeros(n, 13);
  for k = 1:n
    rows(k, :) = str2double(strsplit(strtrim(lines{k})));  % strtod: correctly rounded
  end
end
