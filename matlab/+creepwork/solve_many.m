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
%   core); 'progress': true for a line on stderr after 2 s and then every
%   10 s (contacts done, rate, time to go), a number S for one every S
%   seconds, or a function handle called as f(done, total) as the contacts
%   are solved (about a hundred times). Results are bitwise those of
%   creepwork.solve one by one, with or without progress; the exact model
%   is solved cold (warm_start is ignored).
  [progress, rest] = take_progress(varargin);
  [p, opt] = creepwork.inputs(rest{:});
  if ~isempty(progress)
    progress = guarded(progress);
  end
  try
    r = creepwork.call('solve_many', p, opt.grid, opt.full, opt.threads, progress);
  catch err
    failed = progress_error();
    if ~isempty(failed)
      rethrow(failed); % the progress function's own error, not the gateway's
    end
    rethrow(err);
  end
end

% The progress function, its error kept (the gateway stops and reports a
% failed call of its own).
function handle = guarded(f)
  progress_error([]);
  handle = @(done, total) call_progress(f, done, total);
end

function call_progress(f, done, total)
  try
    f(done, total);
  catch err
    progress_error(err);
    rethrow(err);
  end
end

function err = progress_error(set)
  persistent kept;
  if nargin
    kept = set;
  end
  err = kept;
end

% The 'progress' option, taken out of the name-value pairs, as a function
% handle (or [] when off).
function [handle, rest] = take_progress(args)
  handle = [];
  rest = args;
  k = 1 + (numel(args) >= 1 && isstruct(args{1}));
  while k < numel(rest)
    if ~(ischar(rest{k}) && strcmp(rest{k}, 'progress'))
      k = k + 2;
    else
      value = rest{k + 1};
      rest(k:k + 1) = [];
      if isa(value, 'function_handle')
        handle = value;
      elseif isscalar(value) && (islogical(value) || isnumeric(value)) && ...
             (islogical(value) || (value > 0 && value <= 86400))
        if islogical(value)
          if value
            handle = progress_lines(2, 10);
          end
        else
          handle = progress_lines(value, value);
        end
      else
        error('creepwork:badValue', ['progress must be true, false, a number of seconds ' ...
              'in (0, 86400] or a function handle f(done, total)']);
      end
    end
  end
end

% A function handle that prints the creepwork program's progress line on
% stderr when one is due: the first after `first` seconds, then one every
% `every` seconds.
function handle = progress_lines(first, every)
  start = tic();
  due(first);
  handle = @(done, total) report(done, total, toc(start), every);
end

function report(done, total, seconds, every)
  if seconds < due()
    return;
  end
  rate = done / max(seconds, eps);
  fprintf(2, ['creepwork: solve_many: %d of %d contacts done (%.0f %%), %.0f contacts/s, ' ...
              'about %.0f s to go\n'], done, total, 100 * done / total, rate, (total - done) / rate);
  due(seconds + every);
end

% The time of the next line (one solve_many runs at a time).
function t = due(set)
  persistent next;
  if nargin
    next = set;
  end
  t = next;
end
