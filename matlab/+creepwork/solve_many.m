function r = solve_many(varargin)
%SOLVE_MANY  Many contacts in one call of the C batch API, on every core.
%   R = creepwork.solve_many('a', 7e-3, 'b', 5e-3, 'N', 100e3, ...
%                            'xi_y', linspace(0, 5e-3, 10000))
%
%   creepwork.solve's parameters, each a scalar or an array; the arrays
%   have one value per contact (all the same number of elements), and a
%   scalar stands for every contact. R holds every field of cw_result as an
%   array shaped like the first array input (R.Fx, R.Fy, R.Mz, R.W_macro,
%   ...), R.status (0 where solved, else the contact's status code) and
%   R.message (a cell array: the library's message naming the input of each
%   failed contact, '' elsewhere). Failed contacts hold NaN totals; the
%   others are solved, and nothing is raised for them.
%   Options: 'grid' as creepwork.solve; 'full', true for the totals marked
%   (FULL) in the header (K, W_micro_paper, ...); 'threads' (0: every
%   core). Results are bitwise those of creepwork.solve one by one; the
%   exact model is solved cold (warm_start is ignored).
  [p, opt] = creepwork.inputs(varargin{:});
  r = creepwork.call('solve_many', p, opt.grid, opt.full, opt.threads);
end
