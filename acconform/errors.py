"""The one family of exceptions acconform raises for misuse; physics outcomes are never exceptions."""


class AcconformError(Exception):
    """Root of every error acconform raises on purpose. The CLI turns these into exit 2."""


class InvalidScene(AcconformError, ValueError):
    """A scene, case or record file is malformed or inconsistent.

    `path` names the offending field (e.g. ``landblocks[0].heights``) so the message can
    point at it; `source` names the file when one is known.
    """

    def __init__(self, path: str, problem: str, source: str | None = None):
        self.path = path
        self.problem = problem
        self.source = source
        where = f"{source}: " if source else ""
        super().__init__(f"{where}{path}: {problem}" if path else f"{where}{problem}")

    def in_file(self, source: str) -> "InvalidScene":
        return InvalidScene(self.path, self.problem, source)


class OracleUnavailable(AcconformError):
    """The live oracle cannot run: no ACE assembly configured, wrong runtime, missing member."""


class OracleError(AcconformError):
    """The oracle's machinery (not ACE's physics) failed in a way that is not a verdict."""
