"""A robot: its description read by the generator, its C header compiled, and its methods on
NumPy arrays."""

import math
import numbers
import os

from . import _compiled, _configuration, _floating, _native
from ._errors import generator_error
from ._methods import Method
from ._parameters import Parameters


def _generate(source, families, floating, contacts):
    try:
        return _native.c_header(**source, families=families, floating=floating,
                                contacts=contacts)
    except _native.GeneratorError as error:
        raise generator_error(error) from None


class Robot:
    """A robot's closed-form equations of motion (a serial arm, or a tree such as a hand),
    compiled for this machine.

    Read one with :meth:`from_file` or :meth:`from_urdf` (or ``Robot(path, base=, tip=, tips=,
    tool=, families=, parameters=, check_inertia=)``, which takes the arguments of both). Every method of the Rust trait is a
    method here with the same name (``mass_matrix``, ``inverse_dynamics``, ``forward_dynamics``,
    the hand's pose and Jacobians, and with ``families`` the derivatives or the regressor), on
    one state (arrays of shape ``(n,)``) or a batch (shape ``(N, n)``) in one call; ``methods``
    lists them. ``parameters`` holds the values of the description's symbols (``mass =
    "m1"``), in the order of the C functions' ``params``.

    ``floating=True`` (``from_urdf``, ``from_file``) reads the robot on a free-flying base, as
    ``#[dynamics(base = floating)]`` does, in Pinocchio's free-flyer conventions: ``q`` has
    ``nq = n + 7`` elements (the base position, its quaternion ``[qx, qy, qz, qw]``, the joints),
    the velocity (the methods' ``qd``), acceleration (``qdd``) and ``tau`` have ``nv = n + 6``
    (the base's twist in its own frame, then the joints); its methods are ``FloatingDynamics``'
    (``mass_matrix``, ``bias_forces``, ``inverse_dynamics``, ``generalized_gravity``,
    ``forward_dynamics``, ``mass_matrix_inverse``) and ``integrate`` and ``difference``;
    ``dof`` is ``nv``.

    ``dof`` counts the coordinates; a robot with mimic joints (``q_m = k q_j + o``) has more
    links, one per joint: the regressor's blocks and ``joint_regressor``'s rows. ``joint_rows[i]``
    is the row of τ joint i's columns of ``joint_regressor`` add to (i itself but for a mimic
    joint: the row of the joint it follows).
    """

    def __init__(self, path, *, base=None, tip=None, tips=(), tool=None, families=(),
                 parameters=None, check_inertia=True, floating=False, contacts=False):
        # Where the description comes from, which `equations` reads again.
        self._source = {
            "path": os.fsdecode(path),
            "base": None if base is None else os.fsdecode(base),
            "tip": None if tip is None else os.fsdecode(tip),
            "tips": _names(tips, "tips"),
            "tool": None if tool is None else _tool(tool),
            "check_inertia": bool(check_inertia),
        }
        families = _families(families)
        self._asked = set(families)
        self.floating = bool(floating)
        if contacts and not self.floating:
            raise ValueError("contacts=True is a floating base's (floating=True)")
        generated = _generate(self._source, families, self.floating, bool(contacts))
        self.name = generated["robot"]
        self.dof = generated["dof"]
        self.joint_rows = tuple(generated["joint_rows"])
        self.header = generated["text"]
        self._parameters = Parameters(self.name, generated["fields"])
        if parameters is not None:
            self._parameters.replace(parameters, f"{self.name}: parameters")
        library = _compiled.load(self.header)
        by_method = {}
        for signature in generated["functions"]:
            by_method.setdefault(signature["method"], []).append(signature)
        for name, signatures in by_method.items():
            setattr(self, name, Method(self, library, signatures, self._parameters))
        # A floating base's frames (its kinematics' and contacts'), in their results' order.
        self.frames = tuple(generated["frames"])
        if self.floating:
            # The same for every robot: the runtime's, not the header's.
            for name, method in _configuration.methods(self, _native).items():
                by_method[name] = method
                setattr(self, name, method)
            # The header's kinematics and contacts, through their batch twins, the robot's
            # parameters first where it has any.
            if self.frames:
                prefix = generated["functions"][0]["name"].removesuffix(
                    "_" + generated["functions"][0]["method"])
                for name, method in _floating.methods(self, library, prefix).items():
                    by_method[name] = method
                    setattr(self, name, method)
        self.methods = tuple(by_method)

    @property
    def parameters(self):
        """The values of the description's symbols by name (``None`` until given), in the order
        of the C functions' ``params``: ``robot.parameters["m1"] = 2.0``, or all at once,
        ``robot.parameters = {"m1": 2.0, ...}``."""
        return self._parameters

    @parameters.setter
    def parameters(self, values):
        self._parameters.replace(values, f"{self.name}: parameters")

    def __getattr__(self, name):
        # Only for a name that is not an attribute: a method this robot was built without.
        if name.startswith("_") or "methods" not in self.__dict__:
            raise AttributeError(f"{type(self).__name__!r} object has no attribute {name!r}")
        raise AttributeError(_missing_method(self, name))

    @classmethod
    def from_file(cls, path, *, families=(), tool=None, parameters=None, floating=False,
                  contacts=False):
        """The robot of a description file (TOML or JSON, as ``#[dynamics(file = "...")]``
        reads it).

        ``families``: opt-in families of methods, such as ``("derivatives", "regressor")``;
        ``tool``: the hand frame ``[x, y, z, roll, pitch, yaw]`` in the last link's frame;
        ``parameters``: the value of every symbol of the file (``{"m1": 2.0, "g": 9.81}``), or
        none now and ``robot.parameters`` later. Raises ``DescriptionError`` with the file, line
        and column of a problem, ``ValueError`` for a missing or unknown parameter.
        ``floating=True``: the robot on a free-flying base, its body the file's ``[floating]``
        table; with ``contacts=True``, its contacts too (``contact_dynamics``, ...).
        """
        return cls(path, tool=tool, families=families, parameters=parameters, floating=floating,
                   contacts=contacts)

    @classmethod
    def from_urdf(cls, path, base=None, tip=None, *, tips=(), families=(), check_inertia=True,
                  floating=False, contacts=False):
        """The robot of a URDF file: every moving joint below link ``base`` (by default the
        root link; a tree if they branch), or the chain to link ``tip``, or the branches that
        lead to the links ``tips``. ``check_inertia=False`` keeps published inertias whose
        principal moments break the triangle inequality. ``floating=True``: the robot on a
        free-flying base, the root link (or ``base``) and the links fixed to it its body;
        ``contacts=True``, its contacts too (``contact_dynamics``, ...: their closed form
        triples the header's compile time)."""
        return cls(path, base=base, tip=tip, tips=tips, families=families,
                   check_inertia=check_inertia, floating=floating, contacts=contacts)

    def equations(self, latex=False, kinematics=False):
        """The equations of motion in the book's notation (``kinematics=True``: the hand's pose
        and Jacobians), as text or as LaTeX; a floating base's M, h, g and τ in Pinocchio's
        coordinates."""
        if kinematics and self.floating:
            raise ValueError(f"{self.name}: a floating base's equations have no kinematics "
                             "printout yet; call equations() without kinematics")
        try:
            return _native.equations(**self._source, latex=latex, kinematics=kinematics,
                                     floating=self.floating)
        except _native.GeneratorError as error:
            raise generator_error(error) from None

    def _repr_latex_(self):
        # Jupyter's MathJax reads the `align*` environments; the `%` lines are comments.
        lines = self.equations(latex=True).splitlines()
        return "\n".join(line for line in lines if not line.startswith("%"))

    def __repr__(self):
        if self.floating:
            return (f"<Robot {self.name} on a floating base: {self.dof - 6} joints and the "
                    f"base's 6, {len(self.methods)} methods>")
        return f"<Robot {self.name}: {self.dof} joints, {len(self.methods)} methods>"


def _families(families):
    if isinstance(families, str):
        families = [families]
    families = list(families or ())
    if not all(isinstance(f, str) for f in families):
        raise TypeError(f"families: expected names such as ['derivatives'], got {families!r}")
    return families


def _names(names, what):
    """``names`` as a list of link names: one name (a string) or an iterable of them."""
    if isinstance(names, (str, bytes, os.PathLike)):
        names = [names]
    try:
        return [os.fsdecode(name) for name in names]
    except TypeError:
        raise TypeError(f"{what} = {names!r}: expected link names") from None


def _tool(tool):
    """``tool`` as six finite numbers."""
    expected = "expected six finite numbers [x, y, z, roll, pitch, yaw]"
    try:
        values = list(tool)
    except TypeError:
        raise TypeError(f"tool = {tool!r}: {expected}") from None
    real = all(isinstance(x, numbers.Real) and not isinstance(x, bool) for x in values)
    if len(values) != 6 or not real or not all(math.isfinite(float(x)) for x in values):
        raise ValueError(f"tool = {tool!r}: {expected}")
    return [float(x) for x in values]


_METHOD_TABLE = {name: (family, opt_in) for name, family, opt_in in _native.methods()}


def _missing_method(robot, name):
    """Why ``robot`` has no method ``name``, and how to get it."""
    lacks = f"{robot.name} has no method `{name}`"
    if name not in _METHOD_TABLE:
        return f"{lacks}; its methods: {', '.join(robot.methods)}"
    family, opt_in = _METHOD_TABLE[name]
    if family == "simplify":
        return (f"{lacks}: the simplified models come from a `[simplify]` table in the "
                "description file (an envelope and tolerances; docs/description-files.md)")
    if opt_in and family in robot._asked:
        # Asked for, but the trace left it out (`Equations::add_families`).
        why = ("the base parameters need the robot's lengths and angles as numbers, not "
               "parameters" if family == "base_parameters" else
               f"the family `{family}` has no `{name}` for this robot")
        return f"{lacks}: {why}"
    if opt_in:
        return (f"{lacks}: it belongs to the opt-in family `{family}`, which this robot was "
                f"built without; ask for it with Robot.from_file(path, families=[{family!r}]) "
                f"(or from_urdf(..., families=[{family!r}]))")
    return (f"{lacks}: its result has no elements for this robot (a term it does not have), "
            "so the header has no function for it")

