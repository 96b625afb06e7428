"""The package's exceptions: a description the generator refused, and a solve whose mass matrix
was not positive definite."""

import re

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


class NotPositiveDefinite(np.linalg.LinAlgError):
    """A solve with the LDLᵀ of M met a pivot that is not positive (a singular M, or NaN in the
    inputs) at some states.

    ``states`` are their indices in the batch (``[0]`` for a single state); ``result`` is what
    the method computed for every state, the failed ones included, as it would have returned it.
    """

    def __init__(self, method, states, count, result):
        self.states = states
        self.result = result
        shown = ", ".join(str(i) for i in states[:10]) + (", ..." if len(states) > 10 else "")
        super().__init__(
            f"{method}: M(q) is not positive definite at {len(states)} of {count} states ({shown})"
        )
