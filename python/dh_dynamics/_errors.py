"""The package's exceptions: a description the generator refused, an input that is not finite,
and a solve whose mass matrix was not positive definite."""

from __future__ import annotations

from typing import Any, NamedTuple

import numpy as np


class Diagnostic(NamedTuple):
    """One problem the generator found, as data: the file (``None`` for a mistake in the
    arguments), its 1-based line and column (``None`` where the problem has no place, such as a
    missing file), what is wrong, and a hint where one helps."""

    file: str | None
    line: int | None
    column: int | None
    message: str
    help: str | None = None

    def __str__(self):
        # As the `dynamics` command prints it.
        if self.file is None:
            text = self.message
        elif self.line is None or self.column is None:
            text = f"{self.file}: {self.message}"
        else:
            text = f"{self.file}:{self.line}:{self.column}: {self.message}"
        return text if self.help is None else f"{text}\nhelp: {self.help}"


class DescriptionError(ValueError):
    """The robot's description cannot be read or fails a check.

    ``file``, ``line``, ``column``, ``message`` and ``help`` are those of the first problem
    (``line`` and ``column`` are ``None`` where it has no place, such as a missing file;
    ``help`` where there is no hint); ``diagnostics`` lists every problem as a
    :class:`Diagnostic`, ``problems`` as the ``dynamics`` command prints it,
    ``file:line:col: message``.
    """

    diagnostics: list[Diagnostic]
    problems: list[str]
    file: str | None
    line: int | None
    column: int | None
    message: str
    help: str | None

    def __init__(self, diagnostics):
        self.diagnostics = list(diagnostics)
        self.problems = [str(d) for d in self.diagnostics]
        first = self.diagnostics[0]
        self.file, self.line, self.column = first.file, first.line, first.column
        self.message, self.help = first.message, first.help
        super().__init__("\n".join(self.problems))


def generator_error(error):
    """The exception for the generator's ``GeneratorError``: a mistake in the arguments (no
    file) as a ``ValueError``, a description's problems as a ``DescriptionError``."""
    diagnostics = [Diagnostic(**d) for d in error.diagnostics]
    if all(d.file is None for d in diagnostics):
        return ValueError("\n".join(str(d) for d in diagnostics))
    return DescriptionError(diagnostics)


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
