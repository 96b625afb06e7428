"""A method's input arrays checked and made ready for the C batch functions: every error names
the method, the argument and what was expected.

An input is one state, shape ``(n,)``, or a batch, shape ``(N, n)`` (``N`` may be 0); a 1-D
input beside batches is used for every state, as NumPy broadcasts. Its elements are real
numbers: ``float64``, ``float32``, or integers (computed in ``float64``, as are other float
types); lists are read as NumPy reads them. Booleans, complex numbers, strings, objects and
masked elements are refused. Any layout is taken (views, negative strides, Fortran order): the
C functions are given C-contiguous, aligned copies where the input is not one.
"""

import math

import numpy as np

# The kinds of dtype taken: floats, signed and unsigned integers.
_REAL = "fiu"


def arrays(method, arguments, inputs):
    """The inputs as ``(arrays, dtype)``: each a NumPy array of its argument's dtype, as given
    (1-D or 2-D), in ``float32`` when every input is ``float32``, else ``float64``."""
    given = [_array(method, name, length, x) for (name, length), x in zip(arguments, inputs)]
    float32 = bool(given) and all(a.dtype == np.float32 for a in given)
    dtype = np.dtype(np.float32 if float32 else np.float64)
    return [a.astype(dtype, copy=False) for a in given], dtype


def _array(method, name, length, x):
    expected = f"expected ({length},) for one state or (N, {length}) for N states"
    if type(x) is np.ndarray:
        a = x
    elif np.ma.isMaskedArray(x) and np.ma.is_masked(x):
        raise ValueError(f"{method}: `{name}` has masked elements; {expected}, every element "
                         "a number (fill them: x.filled(value))")
    else:
        try:
            a = np.asarray(x)
        except (ValueError, TypeError) as error:
            raise ValueError(f"{method}: `{name}` is not an array of numbers ({error}); "
                             f"{expected}") from None
    if a.dtype.kind not in _REAL:
        raise TypeError(f"{method}: `{name}` has dtype {a.dtype}; expected real numbers "
                        "(float64, float32 or integers)")
    if a.ndim not in (1, 2) or a.shape[-1] != length:
        raise ValueError(f"{method}: `{name}` has shape {a.shape}; {expected}")
    return a


def batch(method, arguments, given):
    """The number of states ``N`` and whether the call is a batch (any input 2-D); a
    ``ValueError`` where batches differ in length."""
    counts = {a.shape[0] for a in given if a.ndim == 2}
    if len(counts) > 1:
        shapes = ", ".join(f"`{name}` {a.shape}" for (name, _), a in zip(arguments, given))
        raise ValueError(f"{method}: batches of different lengths: {shapes}; expected the "
                         "same N for every (N, n) input")
    return (counts.pop(), True) if counts else (1, False)


def contiguous(given, count):
    """Each input as a C-contiguous, aligned ``(count, n)`` array of its dtype."""
    out = []
    for a in given:
        if a.ndim == 1 and count != 1:
            a = np.broadcast_to(a, (count, a.shape[0]))
        # One state's (n,) is the (1, n) the function reads.
        if not (a.flags.c_contiguous and a.flags.aligned):
            a = a.copy(order="C")
        out.append(a)
    return out


def not_finite(arguments, given, count):
    """The states at which an input is not finite: ``(states, problems)``, the sorted indices
    and, for each argument that has any, its name, its states and its first such element."""
    # A finite sum is finite inputs (NaN and ±inf carry into it; an overflow only takes the
    # long way): one pass each, no mask; a few elements summed as Python floats, cheaper than
    # a NumPy call (a call of one state costs little else).
    total = sum(sum(a.ravel().tolist()) if a.size <= 64 else float(a.sum()) for a in given)
    if math.isfinite(total):
        return [], []
    states = np.zeros(count, bool)
    problems = []
    for (name, _), a in zip(arguments, given):
        bad = ~np.isfinite(a)
        if not bad.any():
            continue
        first = tuple(int(i) for i in np.argwhere(bad)[0])
        where = f"{name}[{', '.join(map(str, first))}] = {float(a[first])!r}"
        if a.ndim == 1:
            # One state used for every state of the batch.
            mine = np.ones(count, bool)
        else:
            mine = bad.any(axis=1)
        states |= mine
        problems.append((name, np.flatnonzero(mine).tolist(), where))
    return np.flatnonzero(states).tolist(), problems
