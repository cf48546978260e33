"""The `acconform` command: one entry point, one subcommand per job.

Exit codes: 0 success; 1 the job ran and found differences (or a case still fails);
2 bad input or configuration (a malformed file, no ACE configured, an unknown option, no
command, an output that cannot be written) -- always one line naming what is wrong, never a
traceback.

Subcommands live in their own modules, imported only when chosen, each with
`add_arguments(parser)` and `run(args) -> int`.
"""

from __future__ import annotations

import argparse
import importlib
import sys

from . import __version__
from .errors import AcconformError

# name -> (module, one-line help). Modules are imported lazily so --help stays instant.
COMMANDS: dict[str, tuple[str, str]] = {
    "validate": ("acconform.commands.validate", "check scene, case and record files; exit 2 naming the first bad field"),
    "check": ("acconform.commands.check", "run a differential campaign, port vs ACE (live or recorded); save shrunk cases"),
    "merge": ("acconform.commands.merge", "join the --json summaries and case files of a campaign's parts "
              "(`check --shard K/N`) into one"),
    "repro": ("acconform.commands.repro", "replay a case file on the port (and live ACE) and print the differences"),
    "explain": ("acconform.commands.explain", "the first step where a case's implementation parts from the reference "
                "trace: tick, step, routine, field, both values and their ulps (--html: a page with pictures)"),
    "report": ("acconform.commands.report", "an HTML index of a failures directory's cases, grouped by first divergence"),
    "show": ("acconform.commands.show", "print a scene, case, record or outcome file readably"),
    "record": ("acconform.commands.record", "run scenes through live ACE and append the records to the recorded-oracle corpus"),
    "coverage": ("acconform.commands.coverage", "how often each port branch fires per 1,000 generated scenes"),
    "bench": ("acconform.commands.bench", "run time against error: the port in exact and fast mode (and the oracle), per kind"),
    "runtime-diff": ("acconform.commands.runtime_diff", "which outcome fields ACE on mono and ACE on .NET 10 answer differently "
                     "(the two corpora, by scene), and which System.Numerics operation causes it"),
    "stress": ("acconform.commands.stress", "numerical stability: ULP nudges, borders, FloorZ, world edges; port vs live ACE"),
    "run": ("acconform.commands.run", "run one scene through the port (or --impl) and print its outcome"),
    "serve": ("acconform.commands.serve", "the built-in port as an implementation speaking acconform.protocol/1 on stdin/stdout"),
    "schema": ("acconform.commands.schema", "print the JSON Schema of scenes, outcomes or traces, generated from the records"),
}


class _Parser(argparse.ArgumentParser):
    """Bad options are bad input like any other: one line naming what is wrong, exit 2 (the usage is
    one `--help` away). Subcommand parsers are made of this class too."""

    def error(self, message):
        self.exit(2, f"{self.prog}: error: {message} (see `{self.prog} --help`)\n")


def build_parser() -> argparse.ArgumentParser:
    parser = _Parser(
        prog="acconform",
        description="Differential conformance testing of Asheron's Call physics: a Python port of "
        "ACE's collision code against ACE itself.",
    )
    parser.add_argument("--version", action="version", version=f"acconform {__version__}")
    sub = parser.add_subparsers(dest="command", metavar="COMMAND")
    for name, (module, help_) in COMMANDS.items():
        p = sub.add_parser(name, help=help_, description=help_)
        p.set_defaults(_module=module)
        importlib.import_module(module).add_arguments(p)
    return parser


# commands whose output is all they do: when the reader goes away (`acconform show FILE | head`)
# they stop quietly, exit 0, as other tools do. Every other command goes on with its output
# dropped and ends with its verdict's exit code (`acconform check | head -1` still exits 1 when
# it found a difference).
STOP_WHEN_READER_GOES = ("show", "schema")


def main(argv: list[str] | None = None) -> int:
    parser = build_parser()
    args = parser.parse_args(argv)
    if not getattr(args, "command", None):
        # as argparse answers a missing required argument: the usage and one line on stderr, exit 2.
        # A bare `acconform` is a command line short of its command, not a request for help
        # (`acconform --help` is), and a script that forgot the command must not pass.
        parser.print_usage(sys.stderr)
        parser.error(f"choose a command: {', '.join(COMMANDS)}")
    if sys.stdout is sys.__stdout__ and sys.stdout is not None:
        sys.stdout = _Stdout(sys.stdout, stop_when_reader_goes=args.command in STOP_WHEN_READER_GOES)
    try:
        code = int(importlib.import_module(args._module).run(args) or 0)
        sys.stdout.flush()  # what is still buffered fails here, as one line, not at exit (a full disk)
        return code
    except AcconformError as e:
        print(f"acconform {args.command}: error: {e}", file=sys.stderr)
        return 2
    except RecursionError:  # a reader without a deep-stack retry met a deeply nested file (acconform/deep.py)
        from .deep import TooDeep

        print(f"acconform {args.command}: error: {TooDeep()}", file=sys.stderr)
        return 2
    except KeyboardInterrupt:
        print(f"acconform {args.command}: interrupted", file=sys.stderr)
        return 130
    except BrokenPipeError:
        _silence_stdout()
        return 0
    except OSError as e:  # a file a command writes, on a full disk or gone read-only during the run
        where = f"{e.filename}: " if e.filename else ""
        print(f"acconform {args.command}: error: {where}{e.strerror or e}", file=sys.stderr)
        return 2


class OutputFailed(AcconformError):
    """Standard output cannot be written (a full disk, /dev/full): the job's output is lost, so it
    is bad input's exit 2, not a verdict."""


class _Stdout:
    """The process's stdout. When the reader of a pipe goes away, a command in STOP_WHEN_READER_GOES
    stops (the BrokenPipeError reaches `main`: exit 0); any other goes on with what it writes after
    that sent to /dev/null, to its verdict's exit code. Any other failure to write is OutputFailed."""

    def __init__(self, stream, stop_when_reader_goes: bool):
        self._stream = stream
        self._stop = stop_when_reader_goes

    def write(self, text: str) -> int:
        try:
            return self._stream.write(text)
        except BrokenPipeError:
            _silence_stdout()
            if self._stop:
                raise
            return len(text)
        except OSError as e:
            raise _failed(e) from None

    def flush(self) -> None:
        try:
            self._stream.flush()
        except BrokenPipeError:
            _silence_stdout()
            if self._stop:
                raise
            self._stream.flush()  # what was buffered goes to /dev/null now
        except OSError as e:
            raise _failed(e) from None

    def __getattr__(self, name):
        return getattr(self._stream, name)


def _failed(e: OSError) -> OutputFailed:
    _silence_stdout()  # what is still buffered goes to /dev/null: the exit-time flush cannot fail again
    return OutputFailed(f"cannot write to standard output ({e.strerror or e}); its output is lost")


def _silence_stdout() -> None:
    """Point stdout at /dev/null so Python's exit-time flush does not raise on the closed pipe again."""
    import os

    try:
        devnull = os.open(os.devnull, os.O_WRONLY)
        os.dup2(devnull, sys.stdout.fileno())
    except (OSError, ValueError):
        pass


if __name__ == "__main__":  # pragma: no cover
    sys.exit(main())
