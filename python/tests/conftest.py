"""What the package's tests share: the repository's robots and data, Pinocchio's models of the
D-H robots (built as the reference data's scripts build them), and a fresh cache of compiled
robots for the session."""

import importlib.util
import pathlib

import numpy as np
import pytest

ROOT = pathlib.Path(__file__).resolve().parents[2]
DATA = ROOT / "tests" / "data"


@pytest.fixture(scope="session", autouse=True)
def fresh_cache(tmp_path_factory):
    """Every robot compiled in this session, not read from a cache an older build wrote."""
    patch = pytest.MonkeyPatch()
    patch.setenv("DH_DYNAMICS_CACHE", str(tmp_path_factory.mktemp("cache")))
    yield
    patch.undo()


def reference_script():
    """`tests/data/forward/make.py`, whose `model_from_dh` built the reference data's Pinocchio
    models from the D-H descriptions (imported by path: it is a script)."""
    spec = importlib.util.spec_from_file_location("forward_make", DATA / "forward" / "make.py")
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def states(n, count, seed):
    """`count` random states of `n` joints, as the reference data draws them."""
    rng = np.random.default_rng(seed)
    q = rng.uniform(-np.pi, np.pi, (count, n))
    qd = rng.uniform(-2.0, 2.0, (count, n))
    qdd = rng.uniform(-5.0, 5.0, (count, n))
    return q, qd, qdd


def scaled_error(got, want):
    """max |got - want| / max(1, max |want|)."""
    got, want = np.asarray(got, float), np.asarray(want, float)
    return float(np.max(np.abs(got - want)) / max(1.0, float(np.max(np.abs(want)))))
