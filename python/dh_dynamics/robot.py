"""A robot: its description read by the generator, its C header compiled, and its methods on
NumPy arrays."""

import os

import numpy as np

from . import _compiled, _native
from ._errors import generator_error
from ._methods import Method


def _generate(words):
    try:
        return _native.c_header(words)
    except _native.GeneratorError as error:
        raise generator_error(str(error)) from None


class Robot:
    """A serial robot's closed-form equations of motion, compiled for this machine.

    Read one with :meth:`from_file` or :meth:`from_urdf`. Every method of the Rust trait is a
    method here with the same name (``mass_matrix``, ``inverse_dynamics``, ``forward_dynamics``,
    the hand's pose and Jacobians, and with ``families`` the derivatives or the regressor), on
    one state (arrays of shape ``(n,)``) or a batch (shape ``(N, n)``) in one call; ``methods``
    lists them.
    """

    def __init__(self, source, families=()):
        # The description's words of the `dynamics` command (the file, and a URDF's chain or a
        # tool), which `equations` gives to `inspect`.
        self._source = list(source)
        generated = _generate(self._source + _families(families))
        self.name = generated["robot"]
        self.dof = generated["dof"]
        self.header = generated["text"]
        library = _compiled.load(self.header)
        by_method = {}
        for signature in generated["functions"]:
            by_method.setdefault(signature["method"], []).append(signature)
        self.methods = tuple(by_method)
        for name, signatures in by_method.items():
            setattr(self, name, Method(self, library, signatures))

    @classmethod
    def from_file(cls, path, *, families=(), tool=None):
        """The robot of a description file (TOML or JSON, as ``#[dynamics(file = "...")]``
        reads it).

        ``families``: opt-in families of methods, such as ``("derivatives", "regressor")``;
        ``tool``: the hand frame ``[x, y, z, roll, pitch, yaw]`` in the last link's frame.
        Raises ``DescriptionError`` with the file, line and column of a problem.
        """
        source = [os.fspath(path)]
        if tool is not None:
            source += ["--tool", ",".join(repr(float(x)) for x in tool)]
        return cls(source, families)

    @classmethod
    def from_urdf(cls, path, base=None, tip=None, *, families=()):
        """The robot of a URDF file: the chain from link ``base`` to link ``tip`` (by default
        the root and the one leaf)."""
        source = [os.fspath(path)]
        if base is not None:
            source += ["--base", base]
        if tip is not None:
            source += ["--tip", tip]
        return cls(source, families)

    def equations(self, latex=False, kinematics=False):
        """The equations of motion in the book's notation (``kinematics=True``: the hand's pose
        and Jacobians), as text or as LaTeX."""
        words = ["inspect", *self._source]
        if latex:
            words.append("--latex")
        if kinematics:
            words.append("--kinematics")
        try:
            return _native.run(words)
        except _native.GeneratorError as error:
            raise generator_error(str(error)) from None

    def _repr_latex_(self):
        # Jupyter's MathJax reads the `align*` environments; the `%` lines are comments.
        lines = self.equations(latex=True).splitlines()
        return "\n".join(line for line in lines if not line.startswith("%"))

    def __repr__(self):
        return f"<Robot {self.name}: {self.dof} joints, {len(self.methods)} methods>"


def _families(families):
    if isinstance(families, str):
        families = [families]
    return ["--with", ",".join(families)] if families else []

