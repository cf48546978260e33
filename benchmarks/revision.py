"""`--against REV` for the benchmarks: run an older revision of acconform in a subprocess.

`revision_env(rev)` checks REV out into a temporary git worktree and yields the environment under
which a subprocess imports *that* revision's `acconform` (a shim directory on PYTHONPATH whose
`acconform` package links to the worktree's acconform/, port/, oracle/ and strategies/). The
worktree is removed afterwards.
"""

from __future__ import annotations

import os
import subprocess
import tempfile
from contextlib import contextmanager
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]


def _shim(worktree: Path) -> Path:
    shim = Path(tempfile.mkdtemp(prefix="acconform-shim-"))
    pkg = shim / "acconform"
    pkg.mkdir()
    for entry in (worktree / "acconform").iterdir():
        (pkg / entry.name).symlink_to(entry)
    for sub in ("port", "oracle", "strategies"):
        (pkg / sub).symlink_to(worktree / sub)
    return shim


@contextmanager
def revision_env(rev: str):
    wt = Path(tempfile.mkdtemp(prefix="acconform-old-")) / "tree"
    subprocess.run(["git", "-C", str(ROOT), "worktree", "add", "--detach", str(wt), rev], check=True, capture_output=True)
    try:
        yield dict(os.environ, PYTHONPATH=str(_shim(wt)))
    finally:
        subprocess.run(["git", "-C", str(ROOT), "worktree", "remove", "--force", str(wt)], capture_output=True)


def child_ms(env, code: str, *args: str, what: str) -> float:
    """Run `code` (a script printing a JSON object with "ms" last) in a fresh Python under `env`
    (this tree's, or a revision's from revision_env) and return its "ms"; its error line ends the
    benchmark, naming `what` failed."""
    import json
    import sys

    r = subprocess.run([sys.executable, "-c", code, *args], env=env, capture_output=True, text=True, cwd="/")
    if r.returncode != 0:
        raise SystemExit(f"{what} failed: {r.stderr.strip().splitlines()[-1:]}")
    return json.loads(r.stdout.strip().splitlines()[-1])["ms"]
