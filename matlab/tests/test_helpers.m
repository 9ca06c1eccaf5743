% The helpers against published values: the header's Hertz example,
% Kalker 1990 Table E.3 (a/b = 1, nu = 0.25: C11 = 4.12, C22 = 3.67,
% C23 = 1.47, C33 = 1.19, tests/data/kalker_cij.csv) and Kalker's
% 1982 check values (kalker1982_checks.csv) to their 4 decimals.
h = creepwork.hertz(1 / (2 * 0.457), 1 / (2 * 0.3), 100e3, 82e9 / (1 - 0.28));
assert(round(h.a * 1e6) == 7170 && round(h.b * 1e6) == 5417 && round(h.p0 / 1e6) == 1229);
c = creepwork.kalker_coefficients(1, 0.25);
table = dlmread(fullfile(getenv('CREEPWORK_TEST_DATA_DIR'), 'kalker_cij.csv'), ',', 1, 0);
row = table(table(:, 2) == 1 & table(:, 3) == 0.25, :);
assert(rows(row) == 1 && max(abs(c - row(4:7))) < 1e-12);
L = creepwork.kalker_flexibilities(7e-3, 5e-3, 82e9, 0.28);
c = creepwork.kalker_coefficients(7 / 5, 0.28);
assert(abs(L(1) - 8 * 7e-3 / (3 * c(1) * 82e9)) < 1e-12 * L(1));
checks = dlmread(fullfile(getenv('CREEPWORK_TEST_DATA_DIR'), 'kalker1982_checks.csv'), ...
                 ',', 1, 0);
assert(rows(checks) == 5);
for k = 1:5
  v = checks(k, :);
  [tx, ty] = creepwork.fastsim_normalised(v(1), v(2), v(3), v(4), v(5), v(6), v(7));
  assert(abs(tx - v(8)) <= 0.5e-4 && abs(ty - v(9)) <= 0.5e-4, sprintf('row %d', k));
end
c = creepwork.constants();
assert(strcmp(creepwork.version(), sprintf('%d.%d.%d', c.CW_VERSION_MAJOR, c.CW_VERSION_MINOR, ...
                                           c.CW_VERSION_PATCH)));
disp('helpers reproduce the published values');
