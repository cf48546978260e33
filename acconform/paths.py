"""Where a command may write: the one rule that an output path is never one of the command's inputs.

Every command that reads files and writes others (merge --json, record --out, check --json,
explain --html, ...) calls `refuse_output_over_input` before it reads or writes anything, so
that a mistyped path costs one line and exit 2, never a user's file.
"""

from __future__ import annotations

import os
from pathlib import Path

from .errors import AcconformError


def refuse_output_over_input(output, inputs, option: str) -> None:
    """AcconformError (exit 2, one line) when `output` is one of `inputs`, or lies inside an input that
    is a directory (a corpus, a failures directory: what is written there would replace, or join,
    what the command reads). `output` None (the option not given) passes."""
    if output is None:
        return
    out = Path(output)
    for given in inputs:
        inp = Path(given)
        if _same(out, inp):
            raise AcconformError(f"{option} {out}: is the input {inp}; writing there would overwrite it, "
                                 "so nothing was done: choose another path")
        if inp.is_dir() and any(_same(parent, inp) for parent in out.resolve().parents):
            raise AcconformError(f"{option} {out}: is inside the input directory {inp}; writing there would "
                                 "change what is read, so nothing was done: choose a path outside it")


def _same(a: Path, b: Path) -> bool:
    """Whether two paths name one file: the same path once links are followed, or (both existing) the
    same inode, as a hard link or a second mount of the directory is."""
    if a.resolve() == b.resolve():
        return True
    try:
        return os.path.samefile(a, b)
    except OSError:
        return False
