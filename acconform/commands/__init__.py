"""One module per `acconform` subcommand: add_arguments(parser) and run(args) -> exit code.

Keep imports at module level light; import the port, the oracle or Hypothesis inside run().
`add_runtime_argument` is the one ``--runtime`` every command that runs scenes takes.
"""

# The runtimes ACE runs on, keyed as acconform.numerics.RUNTIMES (a test checks they agree; named
# here so that building the parser imports no numpy), and the one default every command takes.
RUNTIME_CHOICES = ("mono", "coreclr")
RUNTIME_DEFAULT_HELP = ("default: the runtime of the ACE answers compared with -- a live build's (CoreCLR when "
                        "ACE.Server.runtimeconfig.json is beside it, else mono), a case's -- else coreclr (.NET 10, "
                        "what ACE ships for)")


def runtime_name(value: str) -> str:
    """--runtime's type: a known runtime, or the one line argparse prints (exit 2)."""
    import argparse

    if value not in RUNTIME_CHOICES:
        raise argparse.ArgumentTypeError(f"unknown runtime {value!r}: choose one of {', '.join(sorted(RUNTIME_CHOICES))}")
    return value


def positive_int(value: str) -> int:
    """The type of a count that must be at least 1 (-j, --batch): anything else is the one line
    argparse prints, naming the option and the value (exit 2)."""
    import argparse

    try:
        n = int(value)
    except ValueError:
        raise argparse.ArgumentTypeError(f"expected a whole number of at least 1, got {value!r}") from None
    if n < 1:
        raise argparse.ArgumentTypeError(f"must be at least 1, got {value}")
    return n


def positive_seconds(value: str) -> float:
    """The type of a time limit (--timeout): a finite number of seconds above 0. A limit of 0 or
    less would fail every scene, and nan or inf none (a hang would hold the run forever)."""
    import argparse
    import math

    try:
        s = float(value)
    except ValueError:
        raise argparse.ArgumentTypeError(f"expected a number of seconds, got {value!r}") from None
    if not (math.isfinite(s) and s > 0):
        raise argparse.ArgumentTypeError(f"must be a finite number of seconds above 0, got {value}")
    return s


def add_runtime_argument(p, what: str) -> None:
    """``--runtime mono|coreclr``: `what` says what it chooses in this command; the default is the
    same everywhere (`runtime_or_default`)."""
    p.add_argument("--runtime", type=runtime_name, default=None, metavar="{mono,coreclr}",
                   help=f"{what}; {RUNTIME_DEFAULT_HELP}")


def runtime_or_default(runtime: str | None, oracle=None) -> str:
    """The runtime a command computes as: --runtime, else the runtime of `oracle` (the ACE compared
    with, when there is one), else DEFAULT_RUNTIME (coreclr, .NET 10)."""
    from ..numerics import runtime_named
    from ..oracle import DEFAULT_RUNTIME

    if runtime is not None:
        return runtime
    if oracle is not None:
        return runtime_named(oracle.versions.runtime)
    return DEFAULT_RUNTIME
