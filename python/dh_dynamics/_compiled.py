"""The robot's C header compiled into a shared library with the system's C compiler, cached by
the hash of what went into it, and loaded with ctypes.

The library holds the header's batch functions (``DYNAMICS_BATCH``): each method over ``n``
states in one call, so that a NumPy batch costs one foreign call and no Python loop.

The cache is ``$DH_DYNAMICS_CACHE`` or ``$XDG_CACHE_HOME/dh_dynamics`` (``~/.cache/dh_dynamics``);
where it cannot be written, a private temporary directory for this process, with a warning that
names the directory that failed and the variable that moves it. The compiler is ``$CC`` or the
first of ``cc``, ``gcc``, ``clang``; the flags ``$DH_DYNAMICS_CFLAGS`` or ``-O2 -march=native
-ffp-contract=fast`` (the vector units and fused multiply-adds of this machine; without
``-march=native`` where the compiler refuses it).
"""

import atexit
import ctypes
import hashlib
import os
import platform
import shutil
import subprocess
import sys
import tempfile
import warnings
from pathlib import Path

_DEFAULT_FLAGS = ["-O2", "-march=native", "-ffp-contract=fast"]
_SOURCE = '#define DYNAMICS_BATCH\n#define DYNAMICS_BATCH_API\n#include "robot.h"\n'


class CompilerError(RuntimeError):
    """No C compiler was found, or it failed on the robot's header."""


def _cache_dir():
    if os.environ.get("DH_DYNAMICS_CACHE"):
        return Path(os.environ["DH_DYNAMICS_CACHE"])
    base = os.environ.get("XDG_CACHE_HOME") or Path.home() / ".cache"
    return Path(base) / "dh_dynamics"


def _compiler():
    names = [os.environ["CC"]] if os.environ.get("CC") else ["cc", "gcc", "clang"]
    for name in names:
        path = shutil.which(name)
        if path:
            return path
    raise CompilerError(
        "no C compiler found (tried " + ", ".join(names) + "): the robot's functions are "
        "compiled from its C header; install gcc or clang, or set CC"
    )


def _version(cc):
    try:
        run = subprocess.run([cc, "--version"], capture_output=True, text=True, check=False)
    except OSError as error:
        raise CompilerError(f"{cc} cannot be run: {error}") from None
    return run.stdout


def _machine():
    """What `-march=native` compiles for: the architecture and, on Linux, the CPU's features
    (a cache shared by machines of different CPUs must not hand one the other's library)."""
    features = ""
    try:
        with open("/proc/cpuinfo") as cpuinfo:
            features = next((line for line in cpuinfo if line.startswith(("flags", "Features"))), "")
    except OSError:
        pass
    return platform.machine() + features


def _build(cc, flags, header, library):
    """Compiles ``header`` into ``library``, in a scratch directory beside it, renamed into
    place once whole (two processes building the same robot each get a complete file)."""
    with tempfile.TemporaryDirectory(dir=library.parent) as scratch:
        scratch = Path(scratch)
        (scratch / "robot.h").write_text(header)
        (scratch / "robot.c").write_text(_SOURCE)
        out = scratch / library.name
        command = [cc, "-std=c99", "-shared", "-fPIC", *flags, "-o", str(out), "robot.c", "-lm"]
        try:
            run = subprocess.run(command, cwd=scratch, capture_output=True, text=True,
                                 check=False)
        except OSError as error:
            raise CompilerError(f"{cc} cannot be run: {error}") from None
        if run.returncode != 0:
            return run.stderr
        os.replace(out, library)
    return None


def load(header):
    """The shared library of ``header``: from the cache, or compiled into it."""
    cc = _compiler()
    custom = os.environ.get("DH_DYNAMICS_CFLAGS")
    attempts = [custom.split()] if custom is not None else [_DEFAULT_FLAGS, ["-O2"]]
    errors = []
    for flags in attempts:
        key = hashlib.sha256(
            "\0".join([header, cc, _version(cc), *flags, sys.platform, _machine()]).encode()
        ).hexdigest()[:32]
        library = _cached(_cache_dir() / f"{key}.so")
        if library is None:
            path, error = _build_somewhere(cc, flags, header, f"{key}.so")
            if error is not None:
                errors.append(f"{cc} {' '.join(flags)}:\n{error}")
                continue
            library = ctypes.CDLL(str(path))
        return library
    raise CompilerError("the robot's header did not compile:\n" + "\n".join(errors))


def _cached(path):
    """The library at ``path`` if it is there and loads (a damaged file is built again)."""
    if not path.exists():
        return None
    try:
        return ctypes.CDLL(str(path))
    except OSError:
        return None


def _build_somewhere(cc, flags, header, name):
    """Builds ``name`` in the cache, or where the cache cannot be written in this process's
    temporary directory: its path and the compiler's errors (``None`` if it compiled)."""
    cache = _cache_dir()
    try:
        cache.mkdir(parents=True, exist_ok=True)
        return cache / name, _build(cc, flags, header, cache / name)
    except OSError as failure:
        cache_failure = failure
    try:
        scratch = _scratch_dir()
        path = scratch / name
        # Built here already by this process (the same robot read again).
        error = None if path.exists() else _build(cc, flags, header, path)
    except OSError as failure:
        raise OSError(
            f"dh_dynamics: the cache directory {cache} cannot be written ({cache_failure}), nor "
            f"a temporary directory ({failure}): set DH_DYNAMICS_CACHE to a writable directory"
        ) from None
    warnings.warn(
        f"dh_dynamics: the cache directory {cache} cannot be written ({cache_failure}); the "
        f"robot is compiled in {scratch}, removed at exit. Set DH_DYNAMICS_CACHE to a writable "
        "directory to keep compiled robots between runs.",
        RuntimeWarning,
        stacklevel=5,
    )
    return path, error


_SCRATCH: list[Path] = []


def _scratch_dir():
    """This process's own temporary directory (made once, mode 0700, removed at exit): not a
    shared one, where another user could leave a library for this process to load."""
    if not _SCRATCH:
        _SCRATCH.append(Path(tempfile.mkdtemp(prefix="dh_dynamics-")))
        atexit.register(shutil.rmtree, _SCRATCH[0], ignore_errors=True)
    return _SCRATCH[0]
