"""The package's exceptions: a description the generator refused, an input that is not finite,
and a solve whose mass matrix was not positive definite."""

from __future__ import annotations

import re
from typing import Any

import numpy as np

# `file:line:col: message`, or `file: message` where the problem has no place.
_AT = re.compile(r"^(?P<file>.+?):(?P<line>\d+):(?P<column>\d+): (?P<message>.*)$")
_FILE = re.compile(r"^(?P<file>[^:]+): (?P<message>.*)$")


class DescriptionError(ValueError):
    """The robot's description cannot be read or fails a check.

    ``file``, ``line`` and ``column`` give where the first problem is (``line`` and ``column``
    are ``None`` where it has no place, such as a missing file); ``problems`` lists every problem
    as the ``dynamics`` command prints it, ``file:line:col: message``.
    """

    problems: list[str]
    file: str | None
    line: int | None
    column: int | None
    message: str

    def __init__(self, problems):
        self.problems = list(problems)
        first = self.problems[0]
        self.file = self.line = self.column = None
        self.message = first
        found = _AT.match(first)
        if found:
            self.file = found["file"]
            self.line = int(found["line"])
            self.column = int(found["column"])
            self.message = found["message"]
        else:
            found = _FILE.match(first)
            if found:
                self.file, self.message = found["file"], found["message"]
        super().__init__("\n".join(self.problems))


def generator_error(message):
    """The exception for a message of the generator: a usage error (clap's, which starts with
    ``error:``) as a ``ValueError``, anything else as a ``DescriptionError``."""
    if message.startswith("error:"):
        return ValueError(message.strip())
    return DescriptionError(message.strip().split("\ndynamics: "))


def _listed(states):
    return ", ".join(str(i) for i in states[:10]) + (", ..." if len(states) > 10 else "")


class NonFiniteInput(ValueError):
    """An input of a method is NaN or infinite at some states (the closed forms would give NaN
    there, and a solve would fail there for no fault of M).

    ``states`` are their indices in the batch (``[0]`` for a single state); ``arguments`` the
    names of the inputs that are not finite; ``result`` is what the method computed for every
    state, as it would have returned it (NaN where an input is not finite).
    """

    states: list[int]
    arguments: list[str]
    result: Any

    def __init__(self, method, problems, states, count, result, singular=()):
        # `count` is None for one state (not a batch).
        self.states = states
        self.arguments = [name for name, _, _ in problems]
        self.result = result
        parts = [
            f"`{name}` is not finite"
            + ("" if count is None else f" at {len(mine)} of {count} states ({_listed(mine)})")
            + f": {where}"
            for name, mine, where in problems
        ]
        message = f"{method}: " + "; ".join(parts) + "; expected finite numbers"
        if singular:
            message += (f" (and M(q) is not positive definite at {len(singular)} states "
                        f"where the inputs are finite: {_listed(singular)})")
        super().__init__(message)


class NotPositiveDefinite(np.linalg.LinAlgError):
    """A solve with the LDLᵀ of M met a pivot that is not positive (a singular M) at some
    states whose inputs are finite (non-finite inputs raise :class:`NonFiniteInput`).

    ``states`` are their indices in the batch (``[0]`` for a single state); ``result`` is what
    the method computed for every state, the failed ones included, as it would have returned it.
    """

    states: list[int]
    result: Any

    def __init__(self, method, states, count, result):
        self.states = states
        self.result = result
        super().__init__(
            f"{method}: M(q) is not positive definite at {len(states)} of {count} states "
            f"({_listed(states)})"
        )
