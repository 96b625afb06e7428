"""The robot's parameters: the symbols of its description file (``mass = "m1"``, ``a = "l"``,
``gravity = [0, 0, "-g"]``), which the C functions take as their first argument, ``params``,
in the order the header lists them.

``robot.parameters`` maps each name to its value (``None`` until given), in that order. A
value is set one at a time (``robot.parameters["m1"] = 2.0``), several at once
(``robot.parameters.update(m1=2.0, g=9.81)``), or all at once (``robot.parameters = {...}``,
which must name every one); every value is checked (a real, finite number) before any is
changed. A method called while some have no value says which.
"""

from __future__ import annotations

import math
import numbers
from collections.abc import Iterator, MutableMapping
from typing import Optional

import numpy as np


class Parameters(MutableMapping[str, Optional[float]]):
    """The robot's parameters by name, in the order of the C functions' ``params``."""

    names: tuple[str, ...]

    def __init__(self, robot, names):
        self._robot = robot
        self.names = tuple(names)
        self._values = {name: None for name in self.names}
        self._arrays = None

    def __getitem__(self, name: str) -> float | None:
        if name not in self._values:
            raise KeyError(self._unknown(name))
        return self._values[name]

    def __setitem__(self, name: str, value: float | None) -> None:
        self.update({name: value})

    def __delitem__(self, name):
        raise TypeError(f"{self._robot}: a parameter cannot be removed, only given another value")

    def __iter__(self) -> Iterator[str]:
        return iter(self.names)

    def __len__(self) -> int:
        return len(self.names)

    def __contains__(self, name):
        return name in self._values

    def __repr__(self):
        values = ", ".join(f"{name}={self._values[name]!r}" for name in self.names)
        return f"Parameters({values})"

    def update(self, other=(), /, **named):
        """Gives the parameters named in ``other`` and ``named`` their values; checks them all
        before changing any."""
        given = dict(other, **named)
        checked = {name: self._check(name, value) for name, value in given.items()}
        if checked:
            self._values.update(checked)
            self._arrays = None

    def replace(self, values, where):
        """Gives every parameter its value from the mapping ``values``, which must name each of
        them and no other; ``where`` says who gave it, for the message."""
        if values is None:
            values = {}
        if not hasattr(values, "keys"):
            raise TypeError(f"{where}: expected a dict of the parameters' values, "
                            f"got {type(values).__name__}")
        unknown = [str(name) for name in values if name not in self._values]
        missing = [name for name in self.names if name not in values]
        if unknown or missing:
            problems = []
            if unknown:
                problems.append("no parameter " + ", ".join(f"`{n}`" for n in unknown))
            if missing:
                problems.append("no value for " + ", ".join(f"`{n}`" for n in missing))
            raise ValueError(f"{where}: {'; '.join(problems)}; {self._expected()}")
        self.update(values)

    def arrays(self, method):
        """The values as ``{np.float64: array, np.float32: array}`` for the C functions (a
        snapshot: setting a value later makes new arrays, so that a call running in another
        thread reads one set), ``None`` for float32 where a value is beyond its range; a
        ``ValueError`` naming ``method`` while some have none."""
        arrays = self._arrays
        if arrays is None:
            unset = [name for name in self.names if self._values[name] is None]
            if unset:
                names = ", ".join(f"`{n}`" for n in unset)
                example = ", ".join(f"{n!r}: ..." for n in unset)
                raise ValueError(
                    f"{self._robot}.{method}: the robot's parameters {names} have no value; "
                    f"give them as Robot.from_file(path, parameters={{{example}}}) or "
                    f"robot.parameters[{unset[0]!r}] = value"
                )
            values = np.array([self._values[name] for name in self.names], np.float64)
            with np.errstate(over="ignore"):
                single = values.astype(np.float32)
            # A value beyond float32's range: refused when a float32 call reads it.
            arrays = {np.float64: values, np.float32: single if np.isfinite(single).all() else None}
            self._arrays = arrays
        return arrays

    def _check(self, name, value):
        if name not in self._values:
            raise ValueError(self._unknown(name))
        where = f"{self._robot}: parameter `{name}` = {value!r}"
        if isinstance(value, np.ndarray) and value.ndim == 0:
            value = value[()]
        if isinstance(value, (bool, np.bool_)) or not isinstance(value, numbers.Real):
            raise TypeError(f"{where}: expected a real number")
        try:
            number = float(value)
        except OverflowError:
            number = float("inf")
        if not math.isfinite(number):
            raise ValueError(f"{where}: expected a finite number")
        return number

    def _unknown(self, name):
        return f"{self._robot} has no parameter `{name}`; {self._expected()}"

    def _expected(self):
        if not self.names:
            return "the robot has no parameters"
        return "its parameters: " + ", ".join(self.names)
