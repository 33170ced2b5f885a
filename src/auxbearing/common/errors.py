"""The one exception a user mistake raises.

Every bad value that comes from a person (a TOML file, a command-line option, an API call)
ends as an :class:`InputError` whose message is one line naming the field, the value and the
rule. The command line prints that line and exits with status 2, never a traceback.
"""

from __future__ import annotations


class InputError(ValueError):
    """A value given by the user is missing, malformed or physically impossible.

    Examples
    --------
    >>> str(InputError.for_field("inner_groove_ratio", 0.49, "must be > 0.5"))
    'inner_groove_ratio = 0.49: must be > 0.5'
    """

    @classmethod
    def for_field(cls, field: str, value: object, rule: str) -> InputError:
        """Build the standard one-line message ``field = value: rule``."""
        return cls(f"{field} = {value!r}: {rule}")


class ConvergenceError(RuntimeError):
    """A solver did not reach its tolerance; carries what it reached so nothing is hidden."""

    def __init__(self, message: str, residual: float, iterations: int, case: int | None = None) -> None:
        super().__init__(f"{message} (residual {residual:.3g}, {iterations} iterations)")
        self.message = message
        self.residual = residual
        self.iterations = iterations
        self.case = case  #: index of the failing case in a batch, when there is one
