"""Many contacts in one C call: Batch (a cw_batch handle) and solve_many().

The keywords are solve()'s, each a scalar or an array; they broadcast (numpy
rules) to one shape, and every contact of that shape is one cw_params record
of a numpy structured array whose dtype is generated from the header. One
cw_batch_solve call solves them all on the library's threads, with the GIL
released; Python touches no contact one by one, except failed ones, which
are solved again alone to get each one's message.
"""

import ctypes
from typing import Any, List, Optional, Tuple, Union

import numpy as np

from . import _checks, _errors, _progress
from ._handle import Handle
from ._library import CONSTANTS, DTYPES, address, defaults, filled, lib
from ._params import PARAMS, grid_record, polach_keywords, require_geometry
from ._solver import GridLike, Solver, _grid_for, typed_names

_MESSAGE_LEN = 512
_FLOAT_RESULTS = [n for n in DTYPES["cw_result"].names[1:]
                  if DTYPES["cw_result"].fields[n][0].kind == "f"]


class ManyResult:
    """The totals of many contacts, each an array of the keywords' broadcast
    shape: every cw_result field (Fx, Fy, Mz, W_macro, K, n_contact, ...)
    as an attribute, SI, on the wheel (views into results, no copy).

    status  int array: CW_OK (0) where solved, else the contact's error code
    ok      status == 0
    messages  {index: message} for each failed contact, the library's
              message naming the input (e.g. "nu = 0.6 must lie in [0, 0.5]")
    results   the cw_result structured array itself (shape as above)
    params    the cw_params structured array that was solved

    Failed contacts hold NaN in their float totals and 0 in the integer
    ones. errors() lists them as exceptions, raise_first() raises the first.
    """

    def __init__(self, params, results, status, messages):
        self.params = params
        self.results = results
        self.status = status
        self.ok = status == 0
        self.messages = messages
        self.shape = status.shape
        for name in results.dtype.names[1:]:
            setattr(self, name, results[name])

    def errors(self) -> List[Tuple[Tuple[int, ...], _errors.Error]]:
        """[(index, creepwork.Error), ...] for the failed contacts, in order."""
        return [(i, _errors.error_for(int(self.status[i]), self.messages[i]))
                for i in sorted(self.messages)]

    def raise_first(self) -> None:
        """Raises the first failed contact's exception (with its index); no-op
        when every contact was solved."""
        errors = self.errors()
        if errors:
            index, error = errors[0]
            error.args = ("contact %s: %s" % (index, error.message),)
            raise error

    def __len__(self):
        return self.status.size

    def __repr__(self):
        return "<creepwork.ManyResult shape %s, %d solved, %d failed>" % (
            self.shape, int(self.ok.sum()), len(self.messages))


class Batch(Handle):
    """Many independent contacts on one grid, solved in parallel (cw_batch).

        with creepwork.Batch(grid=None, threads=0) as batch:
            out = batch.solve(a=7e-3, b=5e-3, N=100e3, xi_x=np.linspace(0, 3e-3, 10000))

    threads <= 0 uses every core. Results are bitwise those of one-by-one
    solves, whatever the number of threads; the exact model is solved cold
    (warm_start is ignored). One Batch must be used by one thread at a time.
    """

    def __init__(self, grid: GridLike = None, threads: int = 0) -> None:
        self._handle = ctypes.c_void_p()
        rec = grid_record(grid, "Batch")
        message = ctypes.create_string_buffer(_MESSAGE_LEN)
        status = lib.cw_batch_create(address(rec), int(threads), ctypes.byref(self._handle),
                                     message, _MESSAGE_LEN)
        _errors.check(status, lambda: message.value)
        self._grid = rec
        self._solver = None  # made on the first failure, to name its input

    _destroy = "cw_batch_destroy"
    _last_error = "cw_batch_last_error"

    def _close_parts(self) -> None:
        if getattr(self, "_solver", None) is not None:
            self._solver.close()
            self._solver = None

    def prepare(self, model: Union[str, int]) -> None:
        """cw_batch_prepare: makes a model's memory for every thread now."""
        self._check(lib.cw_batch_prepare(self._live(), int(PARAMS.convert("model", model))))

    def solve(self, params: Optional[np.ndarray] = None, *, full: bool = False, warn: bool = True,
              progress: Any = False, **keywords: Any) -> ManyResult:
        """Solves every contact the keywords describe (solve()'s keywords, each
        a scalar or an array; numpy broadcasting) and returns a ManyResult.
        params: a cw_params structured array (any shape) the keywords
        override. full=True also computes the totals marked (FULL) in the
        header (W_micro_paper, K, ...; CW_SOLVE_FULL). A failed contact does
        not stop the others: see ManyResult.status and messages.
        progress: True for a progress line on stderr after 2 s and then
        every 10 s, a number S for one every S seconds, or a callable
        progress(done, total) called as the contacts are solved."""
        return self._solve(params, keywords, full, warn, progress, "solve", 2)

    def _solve(self, params_in, keywords, full, warn, progress, caller, stacklevel):
        handle = self._live()
        keywords = polach_keywords(keywords, caller)
        typed = typed_names(None, keywords, caller)
        if params_in is None:
            require_geometry(typed, caller)
        recs, _ = _records(params_in, keywords, caller)
        report = _progress.reporter(progress, recs.size, caller)
        if warn:
            _errors.warn_units(_checks.warnings_for(self._grid, recs, typed), stacklevel)
        flat = recs.reshape(-1)
        count = flat.size
        results = filled("cw_result", count)
        status = np.zeros(count, np.intc)
        mode = CONSTANTS["CW_SOLVE_FULL"] if full else CONSTANTS["CW_SOLVE_FORCES"]
        # One call, or with progress about a hundred (bitwise the same results).
        step = max(1, count if report is None else -(-count // _progress.PARTS))
        for first in range(0, count, step):
            last = min(count, first + step)
            code = lib.cw_batch_solve(handle, last - first, address(flat[first:last]), mode,
                                      address(results[first:last]), address(status[first:last]))
            if code != 0 and not status[first:last].any():  # the call failed, no contact did
                _errors.check(code, lambda: lib.cw_batch_last_error(handle))
            if report is not None:
                report(last)
        messages = {}
        bad = np.flatnonzero(status)
        for k in bad:
            index = np.unravel_index(k, recs.shape)
            messages[tuple(int(i) for i in index)] = _checks.as_typed(
                self._message(flat[k], mode, int(status[k])), typed)
        if bad.size:
            for name in _FLOAT_RESULTS:
                results[name][bad] = np.nan
        return ManyResult(recs, results.reshape(recs.shape), status.reshape(recs.shape), messages)

    def _message(self, rec, mode, status):
        """A failed contact's own message: the batch keeps only the first
        one's, so the contact is solved again alone, cold as the batch did."""
        if self._solver is None:
            self._solver = Solver(self._grid)
        one = np.array(rec)
        one["warm_start"] = 0
        code = lib.cw_solver_solve(self._solver._handle, address(one), mode, None)
        if code == status:
            return self._solver.last_error or _errors.SUMMARIES.get(status, "")
        return _errors.SUMMARIES.get(status, "unknown status code")


def _records(params_in, keywords, caller):
    """The cw_params structured array of the broadcast shape of params_in
    (None or a structured array) and the keyword values; and those values
    as numbers (enumeration names mapped), by field."""
    if params_in is None:
        base = defaults("cw_params")
    elif isinstance(params_in, np.ndarray) and params_in.dtype == DTYPES["cw_params"]:
        base = params_in
    else:
        raise TypeError("%s(): params must be a cw_params structured array (creepwork.params, "
                        "or ManyResult.params), got %r" % (caller, type(params_in).__name__))
    converted = {}
    for key, value in keywords.items():
        field = PARAMS.field(key, caller)
        if PARAMS.fields[field]["pointer"]:
            raise TypeError("%s(): %s is a pointer field; solve_many takes it only inside "
                            "params" % (caller, field))
        converted[field] = PARAMS.convert(field, value)
    shape = np.broadcast_shapes(base.shape, *(np.shape(v) for v in converted.values()))
    if params_in is None:
        recs = filled("cw_params", shape)
    else:
        recs = np.empty(shape, DTYPES["cw_params"])
        recs[...] = base
    for field, value in converted.items():
        recs[field] = value
    return recs, converted


def solve_many(params: Optional[np.ndarray] = None, *, grid: GridLike = None, full: bool = False,
               threads: int = 0, warn: bool = True, progress: Any = False,
               **keywords: Any) -> ManyResult:
    """Solves many contacts in one call to the C batch API (cw_batch_solve),
    on threads (threads <= 0: every core), with the GIL released, and returns
    a creepwork.ManyResult of arrays (Fx, Fy, Mz, W_macro, ..., status).

        out = creepwork.solve_many(a=7e-3, b=5e-3, N=100e3,
                                   xi_x=np.linspace(0, 3e-3, 10000))
        out.Fx, out.status, out.messages

    Keywords: solve()'s (help(creepwork.solve)), each a scalar or an array;
    they broadcast to one shape, the shape of every output array. grid as
    solve()'s (one grid for all contacts). full=True also computes the
    totals marked (FULL) in the header. A contact that fails gets its own
    status and message (out.status, out.messages) and NaN totals; the others
    are solved: nothing is raised for them (out.raise_first() raises).
    Results are bitwise those of solve() one by one; the exact model is
    solved cold (warm_start ignored). For repeated calls on one grid keep a
    creepwork.Batch. progress: True for a progress line on stderr after 2 s
    and then every 10 s, a number S for one every S seconds, or a callable
    progress(done, total) called as the contacts are solved."""
    keywords = polach_keywords(keywords, "solve_many")
    grid = _grid_for(grid, params, keywords)
    with Batch(grid, threads) as batch:
        return batch._solve(params, keywords, full, warn, progress, "solve_many", 2)
