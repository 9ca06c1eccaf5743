% Errors carry the identifier creepwork:<status name> of the header's list
% and the library's message naming the input; mistakes on the MATLAB side
% (an unknown parameter, a non-integer count) name it too.
function test_errors()
  ok = {'a', 7e-3, 'b', 5e-3, 'N', 100e3, 'xi_x', 1e-3};
  expect_error(@() creepwork.solve(ok{:}, 'nu', 0.6), 'creepwork:CW_ERR_INVALID_INPUT', '\<nu\>');
  expect_error(@() creepwork.solve(ok{:}, 'model', 'exakt'), ...
               'creepwork:CW_ERR_UNKNOWN_OPTION', 'exakt');
  expect_error(@() creepwork.solve(ok{:}, 'grid', struct('nx', 0)), ...
               'creepwork:CW_ERR_GRID_OUT_OF_RANGE', '\<nx\>');
  expect_error(@() creepwork.solve(ok{:}, 'model', 'exact', 'grid', struct('kind', 'strips')), ...
               'creepwork:CW_ERR_INVALID_INPUT', 'grid');
  expect_error(@() creepwork.solve(ok{:}, 'xi', 1e-3), 'creepwork:unknownField', '''xi''');
  expect_error(@() creepwork.solve(ok{:}, 'model', 'exact', 'max_iterations', 2.5), ...
               'creepwork:notInteger', 'max_iterations');
  expect_error(@() creepwork.solve(ok{:}, 'model', 'exact', 'max_iterations', 1e10), ...
               'creepwork:CW_ERR_INVALID_INPUT', 'max_iterations = 10000000000 is outside');
  expect_error(@() creepwork.solve(ok{:}, 'model', 'exact', 'xi_y', 2e-3, 'phi', 1, ...
                                   'tolerance', 1e-13, 'max_iterations', 1), ...
               'creepwork:CW_ERR_NOT_CONVERGED', 'max_iterations');
  s = creepwork.Solver();
  delete(s);
  expect_error(@() s.solve(ok{:}), 'creepwork:badHandle', 'no such');
  % Every status of the header has its identifier (the list is compiled in).
  c = creepwork.constants();
  assert(c.CW_ERR_INVALID_INPUT == 2 && c.CW_OK == 0);
  disp('errors name their input');
end
