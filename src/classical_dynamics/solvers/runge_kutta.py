"""Adaptive explicit Runge-Kutta pairs, compiled: Dormand-Prince 5(4) and DOP853, with dense output.

One loop serves both pairs (the tableaus are scipy's published coefficients, used as data): step-size
control as in Hairer-Norsett-Wanner II.4 (error norm RMS over components, scale atol + rtol |y|),
dense output (quartic for 5(4), degree 7 for DOP853), events located on the dense output with
`subdivisions` sign checks inside every step (so two sign changes in one step are not missed, unlike
a check at step ends only: scipy #9228), and blow-up detection (a bound on |y|, or the step size
collapsing) that ends the run with its time instead of NaN or a hang.

The right-hand side is a numba function f(t, y, p, out) compiled with the signature RHS_SIG (use
the `rhs_function` decorator); events are g(t, y, p, out) with n_events values, same signature.
They reach the loop as first-class functions typed by that signature, so the loop is compiled once,
cached on disk, and shared by every right-hand side (a dispatcher argument would be typed by its
identity and recompiled in every process).

What a loop is given comes in small groups, each a plain tuple (numba types a plain tuple at a call from
Python in a fraction of a microsecond, a named tuple in about one; the loops unpack them on entry):

    problem   (p, t0, t1, y0)                                   the parameters, the span, the start
    steps     (kind, A, B, C, E5, E3)                           the pair's stages and error estimators
    pair      steps + (dense, A_extra, C_extra)                 ... and its dense output
    control   (rtol, atol, max_steps, bound)                    the step-size controller and its limits
    events    (n_events, directions, terminal, subdivisions)    which sign changes of g(t, y, p) to find
    output    (t_eval, record)                                  what to save besides the final state

(the solver, its controller and what to save as separate values, as diffrax has them).
"""

from __future__ import annotations

import numpy as np
from numba import njit, prange, types
from scipy.integrate._ivp import dop853_coefficients as _d853
from scipy.integrate._ivp.rk import RK45 as _RK45

SAFETY, MIN_FACTOR, MAX_FACTOR = 0.9, 0.2, 10.0

F64, I64, VEC, MAT = types.float64, types.int64, types.float64[::1], types.float64[:, ::1]
RHS_SIG = types.void(F64, VEC, VEC, VEC)  # f(t, y, p, out)
FUNC = types.FunctionType(RHS_SIG)
PROBLEM = types.Tuple((VEC, F64, F64, VEC))
ROWS = types.Tuple((MAT, F64, F64, MAT))  # a batch's problem: one row of P and Y0 per start
STEPS = types.Tuple((I64, MAT, VEC, VEC, VEC, VEC))
PAIR = types.Tuple((I64, MAT, VEC, VEC, VEC, VEC, MAT, MAT, VEC))
CONTROL = types.Tuple((F64, F64, I64, F64))
EVENTS = types.Tuple((I64, types.int64[::1], types.boolean[::1], I64))
OUTPUT = types.Tuple((VEC, types.boolean))


def rhs_function(func):
    """Compile f(t, y, p, out) for the integrators (cached on disk)."""
    return njit(RHS_SIG, cache=True)(func)


class _ByAddress(types.WrapperAddressProtocol):
    """A compiled f(t, y, p, out) handed to the loops by its address, looked up once.

    Passing the dispatcher itself makes numba look the address up at every call (about 20 us), but
    then calls it directly; by address, calls go through the C wrapper (about twice the cost per call).
    So: right-hand sides as themselves, the (usually empty) event function by address.
    """

    def __init__(self, dispatcher):
        from numba.experimental.function_type import _get_wrapper_address

        self.dispatcher = dispatcher
        self._address = _get_wrapper_address(dispatcher, RHS_SIG)

    def __wrapper_address__(self):
        return self._address

    def signature(self):
        return RHS_SIG


_BY_ADDRESS: dict = {}


def by_address(dispatcher) -> _ByAddress:
    if dispatcher not in _BY_ADDRESS:
        _BY_ADDRESS[dispatcher] = _ByAddress(dispatcher)
    return _BY_ADDRESS[dispatcher]


# status codes of a run
SUCCESS, TERMINAL_EVENT, BLOW_UP, STEP_TOO_SMALL, MAX_STEPS = 0, 1, 2, 3, 4
STATUS = {
    SUCCESS: "success",
    TERMINAL_EVENT: "terminal event",
    BLOW_UP: "blow-up",
    STEP_TOO_SMALL: "step size too small (a singularity?)",
    MAX_STEPS: "too many steps",
}


class Tableau:
    """Coefficients of a pair; `kind` 0 = Dormand-Prince 5(4), 1 = DOP853."""

    def __init__(self, name, kind, order, A, B, C, E5, E3, dense, A_extra, C_extra):
        self.name, self.kind, self.order = name, kind, order
        self.A, self.B, self.C = (np.ascontiguousarray(x, dtype=float) for x in (A, B, C))
        self.E5, self.E3 = np.ascontiguousarray(E5, dtype=float), np.ascontiguousarray(E3, dtype=float)
        self.dense = np.ascontiguousarray(dense, dtype=float)
        self.A_extra, self.C_extra = (
            np.ascontiguousarray(A_extra, float),
            np.ascontiguousarray(C_extra, float),
        )

        self.steps = (self.kind, self.A, self.B, self.C, self.E5, self.E3)  # what the final-state loop needs
        self.pair = self.steps + (self.dense, self.A_extra, self.C_extra)  # ... and the dense output


DOPRI5 = Tableau(
    "dopri5", 0, 5, _RK45.A, _RK45.B, _RK45.C, _RK45.E, np.zeros(1), _RK45.P, np.zeros((1, 1)), np.zeros(1)
)
DOP853 = Tableau(
    "dop853",
    1,
    8,
    _d853.A[:12, :12],
    _d853.B,
    _d853.C[:12],
    _d853.E5,
    _d853.E3,
    _d853.D,
    _d853.A[13:, :16],
    _d853.C[13:],
)
TABLEAUS = {"dopri5": DOPRI5, "dop853": DOP853}


@njit(cache=True, inline="always")
def _stages(f, p, t, h, y, y_new, steps, work, n):
    """Fill K[0..s] (K[s] = f(t + h, y_new)) and y_new, with no allocation; work = (K, f_old, tmp); n = y.size
    (a constant of the code where the loop is specialized)."""
    _, A, B, C, _, _ = steps
    K, f_old, tmp = work
    s = B.size
    for j in range(n):
        K[0, j] = f_old[j]
    for i in range(1, s):
        for j in range(n):
            acc = 0.0
            for l in range(i):
                acc += A[i, l] * K[l, j]
            tmp[j] = y[j] + h * acc
        f(t + C[i] * h, tmp, p, K[i])
    for j in range(n):
        acc = 0.0
        for l in range(s):
            acc += B[l] * K[l, j]
        y_new[j] = y[j] + h * acc
    f(t + h, y_new, p, K[s])


@njit(cache=True, inline="always")
def _error_norm(steps, control, K, h, y, y_new, n):
    """RMS error norm, scale atol + rtol max(|y|, |y_new|); inf if y_new is not finite; n = y.size."""
    kind, _, _, _, E5, E3 = steps
    rtol, atol, _, _ = control
    rows = E5.size
    if kind == 0:
        total = 0.0
        for j in range(n):
            if not np.isfinite(y_new[j]):
                return np.inf
            acc = 0.0
            for l in range(rows):
                acc += E5[l] * K[l, j]
            e = h * acc / (atol + max(abs(y[j]), abs(y_new[j])) * rtol)
            total += e * e
        return np.sqrt(total / n)
    n5 = 0.0
    n3 = 0.0
    for j in range(n):
        if not np.isfinite(y_new[j]):
            return np.inf
        scale = atol + max(abs(y[j]), abs(y_new[j])) * rtol
        a5 = 0.0
        a3 = 0.0
        for l in range(rows):
            a5 += E5[l] * K[l, j]
            a3 += E3[l] * K[l, j]
        n5 += (a5 / scale) ** 2
        n3 += (a3 / scale) ** 2
    if n5 == 0.0 and n3 == 0.0:
        return 0.0
    return abs(h) * n5 / np.sqrt((n5 + 0.01 * n3) * n)


@njit(cache=True, inline="always")
def _step_factor(err, exponent):
    """err ** exponent; for DOP853 (exponent -1/8) by three square roots, a third of the cost of pow."""
    if exponent == -0.125:
        return 1.0 / np.sqrt(np.sqrt(np.sqrt(err)))
    return err**exponent


@njit(cache=True, inline="always")
def _max_abs(y, n):
    """max |y[j]| over the n components (n a constant of a specialized loop)."""
    m = 0.0
    for j in range(n):
        m = max(m, abs(y[j]))
    return m


@njit(cache=True, inline="always")
def _min_step(t, h):
    """The smallest step the loops take at t, 10 ulp(t); 0 for a step h far above it (1e-14 |t| is more than
    10 ulp), so that nextafter, a call to libm, is made only near the limit: the same steps, 1 % faster."""
    if h > 1e-14 * abs(t) + 1e-300:
        return 0.0
    return 10.0 * abs(np.nextafter(t, np.inf) - t)


@njit(cache=True)
def _dense_coefficients(f, p, pair, t, h, y_old, y_new, K):
    """Per-step interpolation data: Q (dopri5) or F (dop853), as rows."""
    kind, _, _, _, _, _, dense, A_extra, C_extra = pair
    n = y_old.size
    if kind == 0:
        order = dense.shape[1]
        Q = np.zeros((order, n))
        for r in range(order):
            for j in range(n):
                acc = 0.0
                for l in range(K.shape[0]):
                    acc += K[l, j] * dense[l, r]
                Q[r, j] = acc
        return Q
    # DOP853: three extra stages, then F[0..6]
    Kx = np.zeros((16, n))
    Kx[:13, :] = K
    tmp = np.empty(n)
    for s in range(13, 16):
        a = A_extra[s - 13]
        for j in range(n):
            acc = 0.0
            for l in range(s):
                acc += a[l] * Kx[l, j]
            tmp[j] = y_old[j] + h * acc
        f(t + C_extra[s - 13] * h, tmp, p, Kx[s])
    F = np.zeros((7, n))
    for j in range(n):
        dy = y_new[j] - y_old[j]
        F[0, j] = dy
        F[1, j] = h * Kx[0, j] - dy
        F[2, j] = 2 * dy - h * (Kx[12, j] + Kx[0, j])
    for r in range(4):
        for j in range(n):
            acc = 0.0
            for l in range(16):
                acc += dense[r, l] * Kx[l, j]
            F[3 + r, j] = h * acc
    return F


@njit(cache=True)
def _dense_eval(kind, coeffs, h, y_old, x):
    n = y_old.size
    out = np.empty(n)
    if kind == 0:
        for j in range(n):
            acc = 0.0
            power = x
            for r in range(coeffs.shape[0]):
                acc += coeffs[r, j] * power
                power *= x
            out[j] = y_old[j] + h * acc
        return out
    for j in range(n):
        acc = 0.0
        for i in range(7):
            acc += coeffs[6 - i, j]
            if i % 2 == 0:
                acc *= x
            else:
                acc *= 1 - x
        out[j] = y_old[j] + acc
    return out


@njit(cache=True, inline="always")
def _initial_step(f, p, t0, y0, f0, order, control):
    """Hairer's starting step (scipy's select_initial_step), without temporaries."""
    rtol, atol, _, _ = control
    n = y0.size
    s0 = 0.0
    s1 = 0.0
    for j in range(n):
        scale = atol + abs(y0[j]) * rtol
        s0 += (y0[j] / scale) ** 2
        s1 += (f0[j] / scale) ** 2
    d0, d1 = np.sqrt(s0 / n), np.sqrt(s1 / n)
    h0 = 1e-6 if (d0 < 1e-5 or d1 < 1e-5) else 0.01 * d0 / d1
    y1 = np.empty(n)
    for j in range(n):
        y1[j] = y0[j] + h0 * f0[j]
    f1 = np.empty(n)
    f(t0 + h0, y1, p, f1)
    s2 = 0.0
    for j in range(n):
        scale = atol + abs(y0[j]) * rtol
        s2 += ((f1[j] - f0[j]) / scale) ** 2
    d2 = np.sqrt(s2 / n) / h0
    if d1 <= 1e-15 and d2 <= 1e-15:
        h1 = max(1e-6, h0 * 1e-3)
    else:
        h1 = (0.01 / max(d1, d2)) ** (1.0 / (order + 1))
    return min(100 * h0, h1)


@njit(cache=True)
def _record(ts, ys, n_rec, t, y):
    """Append (t, y) to the step record, doubling its storage when full."""
    if n_rec == ts.size:
        ts = np.concatenate((ts, np.empty(ts.size)))
        ys = np.concatenate((ys, np.empty((ys.shape[0], ys.shape[1]))))
    ts[n_rec] = t
    ys[n_rec] = y
    return ts, ys, n_rec + 1


@njit(RHS_SIG, cache=True)
def _no_events(t, y, p, out):
    pass


@njit((FUNC, FUNC, PROBLEM, PAIR, CONTROL, EVENTS, OUTPUT), cache=True)
def integrate(f, g, problem, pair, control, events, output):
    """The compiled loop. Returns a tuple; see ode.solve for its meaning."""
    p, t0, t1, y0 = problem
    kind, A, B, C, E5, E3, _, _, _ = pair
    steps = (kind, A, B, C, E5, E3)
    rtol, atol, max_steps, bound = control
    n_events, directions, terminal, subdivisions = events
    t_eval, record = output
    n = y0.size
    s = B.size
    order = 5 if kind == 0 else 8
    exponent = -1.0 / (order if kind == 0 else 8.0)  # error estimator order 4 (dopri5), 7 (dop853)
    K = np.zeros((s + 1, n))
    f_old = np.empty(n)
    tmp = np.empty(n)
    work = (K, f_old, tmp)
    y_new = np.empty(n)
    f(t0, y0, p, f_old)
    nfev = 1
    h = _initial_step(f, p, t0, y0, f_old, order, control)
    nfev += 1
    t = t0
    y = y0.copy()
    n_eval = t_eval.size
    y_eval = np.full((n_eval, n), np.nan)
    k_eval = 0
    while k_eval < n_eval and t_eval[k_eval] <= t0:
        y_eval[k_eval] = y0
        k_eval += 1
    cap = 1024 if record else 1
    ts = np.empty(cap)
    ys = np.empty((cap, n))
    n_rec = 0
    if record:
        ts[0] = t0
        ys[0] = y0
        n_rec = 1
    ev_t = np.empty(64)
    ev_y = np.empty((64, n))
    ev_i = np.empty(64, dtype=np.int64)
    n_ev = 0
    g_old = np.empty(max(n_events, 1))
    g_new = np.empty(max(n_events, 1))
    g_mid = np.empty(max(n_events, 1))  # the events at a bisection point (tmp is the stages' scratch)
    if n_events > 0:
        g(t0, y0, p, g_old)
    naccept = 0
    nreject = 0
    status = SUCCESS
    t_stop = t1
    while t < t1:
        if naccept >= max_steps:
            status = MAX_STEPS
            break
        rejected = False
        accepted = False
        while not accepted:
            if h < _min_step(t, h):
                status = STEP_TOO_SMALL
                break
            t_new = min(t + h, t1)
            h = t_new - t
            _stages(f, p, t, h, y, y_new, steps, work, n)
            nfev += s
            err = _error_norm(steps, control, K, h, y, y_new, n)
            if err < 1.0:
                factor = MAX_FACTOR if err == 0.0 else min(MAX_FACTOR, SAFETY * _step_factor(err, exponent))
                if rejected:
                    factor = min(1.0, factor)
                h_next = h * factor
                accepted = True
            else:
                h *= (
                    MIN_FACTOR
                    if not np.isfinite(err)
                    else max(MIN_FACTOR, SAFETY * _step_factor(err, exponent))
                )
                rejected = True
                nreject += 1
        if status != SUCCESS:
            break
        naccept += 1
        blown = _max_abs(y_new, n) > bound
        need_dense = (k_eval < n_eval and t_eval[k_eval] <= t_new) or n_events > 0 or blown
        coeffs = np.zeros((1, 1))
        if need_dense:
            coeffs = _dense_coefficients(f, p, pair, t, h, y, y_new, K)
            if kind == 1:
                nfev += 3
        # events: sign changes at sub-points of the step, each refined by bisection on the dense output
        stop_here = False
        if n_events > 0:
            x_prev = 0.0
            g_prev = g_old.copy()
            for sub in range(1, subdivisions + 1):
                x_sub = sub / subdivisions
                y_sub = y_new if sub == subdivisions else _dense_eval(kind, coeffs, h, y, x_sub)
                g(t + x_sub * h, y_sub, p, g_new)
                for e in range(n_events):
                    up = g_prev[e] < 0.0 <= g_new[e]
                    down = g_prev[e] > 0.0 >= g_new[e]
                    if (up and directions[e] >= 0) or (down and directions[e] <= 0):
                        lo, hi = x_prev, x_sub
                        g_lo = g_prev[e]
                        for _ in range(80):
                            mid = 0.5 * (lo + hi)
                            g(t + mid * h, _dense_eval(kind, coeffs, h, y, mid), p, g_mid)
                            if (g_mid[e] < 0.0) == (g_lo < 0.0) and g_mid[e] != 0.0:
                                lo, g_lo = mid, g_mid[e]
                            else:
                                hi = mid
                            if (hi - lo) * abs(h) <= 4e-16 * max(abs(t), 1.0):
                                break
                        if n_ev == ev_t.size:
                            ev_t = np.concatenate((ev_t, np.empty(ev_t.size)))
                            ev_y = np.concatenate((ev_y, np.empty((ev_y.shape[0], n))))
                            ev_i = np.concatenate((ev_i, np.empty(ev_i.size, dtype=np.int64)))
                        ev_t[n_ev] = t + hi * h
                        ev_y[n_ev] = _dense_eval(kind, coeffs, h, y, hi)
                        ev_i[n_ev] = e
                        n_ev += 1
                        if terminal[e]:
                            stop_here = True
                            t_stop = t + hi * h
                if stop_here:
                    break
                g_prev[:] = g_new[:n_events]
                x_prev = x_sub
            g_old[:] = g_new[:n_events] if n_events > 0 else g_old
        # blow-up: |y| leaves the bound inside this step; locate the crossing on the dense output
        if blown:
            lo, hi = 0.0, 1.0
            for _ in range(80):
                mid = 0.5 * (lo + hi)
                if _max_abs(_dense_eval(kind, coeffs, h, y, mid), n) > bound:
                    hi = mid
                else:
                    lo = mid
            t_stop = t + hi * h
        t_end_step = t_stop if (stop_here or blown) else t_new
        while k_eval < n_eval and t_eval[k_eval] <= t_end_step:
            x = (t_eval[k_eval] - t) / h
            y_eval[k_eval] = y_new if x >= 1.0 else _dense_eval(kind, coeffs, h, y, x)
            k_eval += 1
        if stop_here or blown:
            y = _dense_eval(kind, coeffs, h, y, (t_stop - t) / h)
            t = t_stop
            status = TERMINAL_EVENT if stop_here else BLOW_UP
            if record:
                ts, ys, n_rec = _record(ts, ys, n_rec, t, y)
            break
        t = t_new
        y, y_new = y_new, y  # swap buffers: no copy, no allocation
        f_old[:] = K[s]
        h = h_next
        if record:
            ts, ys, n_rec = _record(ts, ys, n_rec, t, y)
    return (
        status,
        t,
        y,
        y_eval,
        nfev,
        naccept,
        nreject,
        ts[:n_rec],
        ys[:n_rec],
        ev_t[:n_ev],
        ev_y[:n_ev],
        ev_i[:n_ev],
    )


def _final_state_loop(f, problem, steps, control):
    """The final state: `_final_state_steps` for a state of any dimension."""
    return _final_state_steps(f, problem, steps, control, problem[3].size)


@njit(cache=True, inline="always")
def _final_state_steps(f, problem, steps, control, n):
    """The loop of `integrate` without dense output, events or records: the final state only, of a state of
    dimension n (a constant of the code in a specialized loop, whose loops over it are then unrolled).

    It takes exactly the steps `integrate` takes (the same stages, error norm and controller), so the two
    give identical results (a test holds them to it); it stops at the first step that leaves the bound and
    reports BLOW_UP there, for the caller to locate the crossing with `integrate`. About twice as fast per
    step: the features it leaves out cost as much as the step of a small system. The step-acceptance block
    is written out in both loops on purpose: as a shared compiled helper it made the loop 50 % slower
    (27 -> 40 us on the HNW body), the price of passing a dozen arrays per step.
    """
    p, t0, t1, y0 = problem
    kind, _, B, _, _, _ = steps
    _, _, max_steps, bound = control
    s = B.size
    order = 5 if kind == 0 else 8
    exponent = -1.0 / (order if kind == 0 else 8.0)
    K = np.zeros((s + 1, n))
    f_old = np.empty(n)
    tmp = np.empty(n)
    work = (K, f_old, tmp)
    y_new = np.empty(n)
    f(t0, y0, p, f_old)
    nfev = 1
    h = _initial_step(f, p, t0, y0, f_old, order, control)
    nfev += 1
    t = t0
    y = y0.copy()
    naccept = 0
    nreject = 0
    status = SUCCESS
    h_next = h
    while t < t1:
        if naccept >= max_steps:
            status = MAX_STEPS
            break
        rejected = False
        accepted = False
        while not accepted:
            if h < _min_step(t, h):
                status = STEP_TOO_SMALL
                break
            t_new = min(t + h, t1)
            h = t_new - t
            _stages(f, p, t, h, y, y_new, steps, work, n)
            nfev += s
            err = _error_norm(steps, control, K, h, y, y_new, n)
            if err < 1.0:
                factor = MAX_FACTOR if err == 0.0 else min(MAX_FACTOR, SAFETY * _step_factor(err, exponent))
                if rejected:
                    factor = min(1.0, factor)
                h_next = h * factor
                accepted = True
            else:
                h *= (
                    MIN_FACTOR
                    if not np.isfinite(err)
                    else max(MIN_FACTOR, SAFETY * _step_factor(err, exponent))
                )
                rejected = True
                nreject += 1
        if status != SUCCESS:
            break
        naccept += 1
        if _max_abs(y_new, n) > bound:
            status = BLOW_UP
            break
        t = t_new
        y, y_new = y_new, y
        for j in range(n):
            f_old[j] = K[s, j]
        h = h_next
    return status, t, y, nfev, naccept, nreject


final_state = njit((FUNC, PROBLEM, STEPS, CONTROL), cache=True)(_final_state_loop)
_SPECIALIZED: dict = {}
METHOD_INDEX = {name: i for i, name in enumerate(TABLEAUS)}  # a method as specialized loops take it
_SPECIALIZED_ROWS: dict = {}
_final_state_any = njit(_final_state_loop)


@njit((FUNC, ROWS, STEPS, CONTROL), cache=True)
def final_state_rows(f, rows, steps, control):
    """The final-state loop over the rows of Y0 (and of P) in one compiled call; rows = (P, t0, t1, Y0)."""
    P, t0, t1, Y0 = rows
    m, n = Y0.shape
    final = np.empty((m, n))
    status = np.empty(m, dtype=np.int64)
    t_end = np.empty(m)
    for i in range(m):
        r = final_state(f, (P[i], t0, t1, Y0[i]), steps, control)
        status[i], t_end[i], final[i] = r[0], r[1], r[2]
    return status, t_end, final


def specialized_final_state_rows(rhs):
    """final_state_rows compiled for this right-hand side, the rows shared out over the cores."""
    if rhs not in _SPECIALIZED_ROWS:

        def rows_of(rows, steps, control):
            P, t0, t1, Y0 = rows
            m, n = Y0.shape
            final = np.empty((m, n))
            status = np.empty(m, dtype=np.int64)
            t_end = np.empty(m)
            for i in prange(m):
                r = _final_state_any(rhs, (P[i], t0, t1, Y0[i]), steps, control)
                status[i], t_end[i], final[i] = r[0], r[1], r[2]
            return status, t_end, final

        _SPECIALIZED_ROWS[rhs] = njit(parallel=True)(rows_of)
    return _SPECIALIZED_ROWS[rhs]


def specialized_final_state(rhs, dimension: int):
    """The final-state loop compiled for this right-hand side and this dimension of the state alone:
    run(which, p, t0, t1, y0, rtol, atol, max_steps, bound) -> (status, t, y, nfev, naccept, nreject), with
    which = METHOD_INDEX[method] and y0.size == dimension.

    The right-hand side and the tableaus are constants of the compiled code, so its calls are direct (not
    through a function pointer), and the call from Python passes plain numbers and arrays (a tuple argument
    costs numba about a microsecond per call to type): about twice as fast again. The dimension is a constant
    too, so the loops over the state's components unroll: 6 % less on the HNW body (3 components). Each costs
    several seconds of compilation (6 to 10 s on 2 cores) on its first call in a process; numba cannot cache
    it on disk (the right-hand side is a dynamic global), so it is opt-in.
    """
    key = (rhs, int(dimension))
    if key not in _SPECIALIZED:
        tableaus = tuple(tableau.steps for tableau in TABLEAUS.values())
        n = int(dimension)

        def run(which, p, t0, t1, y0, rtol, atol, max_steps, bound):
            if y0.size != n:
                raise ValueError("the state's dimension is not the one this loop was compiled for")
            return _final_state_steps(
                rhs, (p, t0, t1, y0), tableaus[which], (rtol, atol, max_steps, bound), n
            )

        _SPECIALIZED[key] = njit(run)
    return _SPECIALIZED[key]
