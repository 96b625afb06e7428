"""The methods' inputs fuzzed (hypothesis): any shape (0-d to 3-d, wrong lengths, empty
batches), dtype (integers, bool, float16, float32, float64 either byte order, long double,
complex, object), value (NaN, ±inf), layout (views, negative strides, Fortran order,
unaligned, read-only) or a list. Whatever the inputs, a call returns or raises a ``TypeError``
or ``ValueError`` naming the method and the argument: no crash. Inputs that are arrays of finite
real numbers of the right shapes give, bit for bit, what the same numbers give as C-contiguous
``float64`` (or ``float32``) arrays, and are not modified."""

import math

import numpy as np
import pytest

hypothesis = pytest.importorskip("hypothesis")
from hypothesis import HealthCheck, given, settings  # noqa: E402
from hypothesis import strategies as st  # noqa: E402
from hypothesis.extra import numpy as hnp  # noqa: E402

import dh_dynamics  # noqa: E402
from conftest import ROOT  # noqa: E402

# One method of each kind of result: a vector, a value, a solve's status, a struct, a wrench.
METHODS = ["inverse_dynamics", "kinetic_energy", "forward_dynamics",
           "forward_dynamics_derivatives", "joint_torques_for_hand_wrench", "mass_matrix"]
DTYPES = [np.float64, np.float32, np.float16, np.longdouble, ">f8", ">f4", np.int64, np.int8,
          np.uint16, np.bool_, np.complex128]


@pytest.fixture(scope="module")
def arm():
    """Niku's Example 6.3 (point masses on a 2R arm): M is positive definite at every q."""
    return dh_dynamics.Robot.from_file(
        ROOT / "robots" / "niku_example_6_3.toml", families=["derivatives"],
        parameters={"l1": 0.7, "l2": 0.5, "m1": 2.0, "m2": 1.5, "g": 9.81})


@st.composite
def argument(draw, length, count):
    """One argument: mostly a plausible shape, sometimes any, in any dtype, layout or list."""
    plausible = st.sampled_from([(length,), (count, length), (count, length), (0, length)])
    shape = draw(st.one_of(
        plausible, plausible, plausible, plausible,
        st.sampled_from([(), (length + 1,), (count, length - 1), (count, length, 1), (1, 0)]),
        hnp.array_shapes(min_dims=0, max_dims=3, min_side=0, max_side=4),
    ))
    # Half of them float64, and three in four finite: most calls of valid inputs.
    dtype = np.dtype(draw(st.one_of(st.just(np.float64), st.sampled_from(DTYPES))))
    finite = draw(st.integers(0, 3)) > 0 or dtype.kind not in "fc"
    elements = None
    if dtype.kind == "f" and finite:
        elements = st.floats(-3, 3, width=min(64, 8 * dtype.itemsize))
    elif dtype.kind in "iu":
        elements = st.integers(-3 if dtype.kind == "i" else 0, 3)
    if dtype == np.longdouble:
        elements = st.floats(-3, 3) if finite else st.floats(allow_nan=True)
    a = draw(hnp.arrays(dtype, shape, elements=elements))
    layout = draw(st.sampled_from(["as is", "strided", "reversed", "fortran", "unaligned",
                                   "read-only", "list", "object", "masked"]))
    return laid_out(a, layout)


def laid_out(a, layout):
    if layout == "strided" and a.ndim:
        wide = np.repeat(a, 2, axis=-1)
        return wide[..., ::2]
    if layout == "reversed" and a.ndim:
        return a[::-1].copy()[::-1]
    if layout == "fortran":
        return np.asfortranarray(a)
    if layout == "unaligned":
        raw = np.zeros(a.nbytes + 1, np.uint8)
        b = raw[1:].view(a.dtype).reshape(a.shape)
        b[...] = a
        return b
    if layout == "read-only":
        a = a.copy()
        a.flags.writeable = False
        return a
    if layout == "list":
        return a.tolist()
    if layout == "object":
        return a.astype(object)
    if layout == "masked":
        return np.ma.masked_array(a, mask=np.zeros(a.shape, bool) if a.ndim else False)
    return a


def valid(inputs, arguments):
    """Whether the inputs are what the methods take: arrays of finite real numbers, each of
    shape (n,) or (N, n), every N the same; and the dtype of the call."""
    arrays = []
    for x, (_, length) in zip(inputs, arguments):
        try:
            a = np.asarray(x)
        except ValueError:
            return False, None
        if a.dtype.kind not in "fiu" or a.ndim not in (1, 2) or a.shape[-1] != length:
            return False, None
        if not np.isfinite(a.astype(np.float64)).all():
            return False, None
        arrays.append(a)
    if len({a.shape[0] for a in arrays if a.ndim == 2}) > 1:
        return False, None
    float32 = all(a.dtype == np.float32 for a in arrays)
    return True, np.float32 if float32 else np.float64


@settings(max_examples=600, deadline=None, database=None,
          suppress_health_check=[HealthCheck.too_slow])
@given(data=st.data())
def test_any_input_returns_or_names_the_method_and_the_argument(arm, data):
    name = data.draw(st.sampled_from(METHODS))
    method = getattr(arm, name)
    arguments = method._arguments
    count = data.draw(st.integers(0, 3))
    inputs = [data.draw(argument(length, count), label=arg) for arg, length in arguments]
    before = [np.array(x, dtype=object, copy=True) for x in inputs]
    ok, dtype = valid(inputs, arguments)
    try:
        got = method(*inputs)
    except (TypeError, ValueError) as error:
        message = str(error)
        assert message.startswith(f"niku_example_6_3.{name}"), message
        assert any(f"`{arg}`" in message for arg, _ in arguments), message
        assert not ok, f"refused valid inputs: {message}"
        hypothesis.event(f"refused: {type(error).__name__}")
        return
    assert ok, "took inputs it should refuse"
    hypothesis.event(f"computed, N = {count}" if any(np.ndim(x) == 2 for x in inputs)
                     else "computed, one state")
    want = method(*(np.array(np.asarray(x), dtype=dtype, order="C") for x in inputs))
    for g, w in zip(got if isinstance(got, tuple) else [got],
                    want if isinstance(want, tuple) else [want]):
        if isinstance(g, float):
            # A scalar of one state is a Python float.
            assert isinstance(w, float) and (g == w or (math.isnan(g) and math.isnan(w)))
            continue
        assert g.dtype == w.dtype == dtype and g.shape == w.shape
        # Finite inputs can overflow (q̇ of 1e153 squared): NaN on both sides is the same.
        assert np.array_equal(g, w, equal_nan=True)
    for x, b in zip(inputs, before):
        assert np.array_equal(np.array(x, dtype=object), b)


def test_an_empty_batch_gives_empty_results(arm):
    empty = np.zeros((0, 2))
    assert arm.inverse_dynamics(empty, empty, empty).shape == (0, 2)
    assert arm.inverse_dynamics(empty, [0.0, 0.0], [0, 0]).shape == (0, 2)
    assert arm.kinetic_energy(empty, empty).shape == (0,)
    assert arm.mass_matrix(empty.astype(np.float32)).dtype == np.float32
    d = arm.forward_dynamics_derivatives(empty, empty, empty)
    assert d.qdd.shape == (0, 2) and d.dqdd_dq.shape == (0, 2, 2)
    assert arm.joint_torques_for_hand_wrench(empty, np.zeros(6)).shape == (0, 2)


def test_the_messages_say_what_was_expected(arm):
    cases = [
        ((np.float64(0.5), [0, 0], [0, 0]),
         ValueError, r"inverse_dynamics: `q` has shape \(\); expected \(2,\) for one state or "
                     r"\(N, 2\) for N states"),
        ((np.zeros((3, 2, 1)), [0, 0], [0, 0]), ValueError, r"`q` has shape \(3, 2, 1\)"),
        (([0, 0], np.zeros(2, complex), [0, 0]),
         TypeError, r"`qd` has dtype complex128; expected real numbers"),
        (([0, 0], [0, 0], [True, False]), TypeError, r"`qdd` has dtype bool"),
        (([0, 0], [0, 0], ["1", "2"]), TypeError, r"`qdd` has dtype <U1"),
        (([0, 0], [0, None], [0, 0]), TypeError, r"`qd` has dtype object"),
        (([0, 0], [[0, 0], [0]], [0, 0]), ValueError, r"`qd` is not an array of numbers"),
        ((np.zeros((2, 2)), np.zeros((3, 2)), [0, 0]),
         ValueError, r"batches of different lengths: `q` \(2, 2\), `qd` \(3, 2\), `qdd` \(2,\)"),
        ((np.ma.masked_array([0.0, 1.0], mask=[0, 1]), [0, 0], [0, 0]),
         ValueError, r"`q` has masked elements"),
    ]
    for inputs, kind, pattern in cases:
        with pytest.raises(kind, match=pattern):
            arm.inverse_dynamics(*inputs)
    with pytest.raises(TypeError, match=r"niku_example_6_3\.inverse_dynamics\(q, qd, qdd\) "
                                        r"takes 3 arrays, 4 given; no argument `tau`"):
        arm.inverse_dynamics([0, 0], [0, 0], qdd=[0, 0], tau=[0, 0])
    with pytest.raises(TypeError, match="`q` given twice"):
        arm.inverse_dynamics([0, 0], [0, 0], [0, 0], q=[0, 0])
    by_name = arm.inverse_dynamics(qdd=[1.0, 0], q=[0.1, 0.2], qd=[0, 0.3])
    assert np.array_equal(by_name, arm.inverse_dynamics([0.1, 0.2], [0, 0.3], [1.0, 0]))
    for tool in ([0, 0, 0.1], [0, 0, np.nan, 0, 0, 0], "0,0,0,0,0,0", [True] * 6):
        with pytest.raises((TypeError, ValueError), match=r"tool = .*: expected six finite"):
            dh_dynamics.Robot.from_file(ROOT / "robots" / "puma560.toml", tool=tool)
