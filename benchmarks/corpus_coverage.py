"""Branch coverage of port/ by a runtime's corpus replay alone (issue 24).

    python benchmarks/corpus_coverage.py [--runtime coreclr|mono] [-n N] [-j 2] [--json FILE]
                                         [--missed FILE] [--markdown FILE]

Replays the recorded corpus of `--runtime` (every record, or a stratified sample of -n) through
the port, computing as that runtime does, under coverage.py with branch measurement restricted to
the port's own source, and prints per module: statements, branches, branches taken, and the
percentages, then the total. `--missed FILE` lists every branch the replay never took as
`module:line->line` (exit arcs as `->exit`), the input for the list of branches ACE cannot take;
`--markdown` writes the table as docs/corpus-coverage.md keeps it. Workers are forked processes,
each with its own coverage data, combined at the end. Outcomes are compared with the one
comparator, and the number of records that differ is printed: coverage of a replay that differs
is not coverage of a correct port.

coverage.py is not a dependency of acconform; install it beside it (it is among the wheels).
A branch-traced replay costs about 3-4x a plain one.
"""

from __future__ import annotations

import argparse
import json
import multiprocessing
import sys
import tempfile
import time
from pathlib import Path


def _port_dir() -> Path:
    """port/'s source directory, found without importing it (its imports are measured)."""
    import importlib.util

    return Path(importlib.util.find_spec("acconform.port").origin).resolve().parent


def _replay(args):
    """Worker: replay `keys` of the corpus under coverage; returns (n, differing, data file)."""
    corpus, runtime, keys, data_file = args
    import coverage

    from acconform.compare import compare
    from acconform.oracle.recorded import RecordedOracle
    from acconform.port.run import run_scene

    oracle = RecordedOracle(corpus)
    cov = coverage.Coverage(branch=True, source=[str(_port_dir())], data_file=data_file)
    differing = 0
    cov.start()
    try:
        for key in keys:
            rec = oracle._record(key)
            if compare(run_scene(rec.scene, runtime=runtime), rec.outcome):
                differing += 1
    finally:
        cov.stop()
        cov.save()
    return len(keys), differing


def _import_port(data_file: str) -> None:
    """Import every port module under coverage, so that what runs at import (definitions, tables)
    counts: the workers are forked after it and trace only the replay."""
    import importlib
    import pkgutil

    import coverage

    cov = coverage.Coverage(branch=True, source=[str(_port_dir())], data_file=data_file)
    cov.start()
    try:
        import acconform.port as port

        for m in pkgutil.walk_packages(port.__path__, "acconform.port."):
            importlib.import_module(m.name)
    finally:
        cov.stop()
        cov.save()


def measure(runtime: str, corpus: Path | None, n: int | None, seed: int, workers: int):
    """(coverage.Coverage with the combined data, records replayed, records differing, seconds)."""
    import coverage

    tmp = Path(tempfile.mkdtemp(prefix="acconform-cov-"))
    imports = str(tmp / ".coverage.imports")
    _import_port(imports)  # before anything else imports the port
    from acconform.oracle import default_corpus
    from acconform.oracle.recorded import RecordedOracle

    corpus = corpus or default_corpus(runtime)
    keys = RecordedOracle(corpus).select(n=n, seed=seed, runtime=None)
    chunks = [keys[w::workers] for w in range(workers)]
    jobs = [(corpus, runtime, chunk, str(tmp / f".coverage.{w}")) for w, chunk in enumerate(chunks) if chunk]
    t0 = time.perf_counter()
    if workers == 1:
        results = [_replay(jobs[0])]
    else:
        with multiprocessing.get_context("fork").Pool(len(jobs)) as pool:
            results = pool.map(_replay, jobs)
    seconds = time.perf_counter() - t0
    cov = coverage.Coverage(branch=True, source=[str(_port_dir())], data_file=str(tmp / ".coverage"))
    cov.combine([imports] + [j[3] for j in jobs])
    cov.save()
    return cov, sum(r[0] for r in results), sum(r[1] for r in results), seconds


def analyse(cov) -> tuple[list[dict], list[str]]:
    """Per-module rows (name, statements, missed statements, branches, taken) and the missed arcs."""
    root = _port_dir()
    rows, missed = [], []
    data = cov.get_data()
    for path in sorted(data.measured_files()):
        p = Path(path)
        if root not in p.parents:
            continue
        name = str(p.relative_to(root))
        a = cov._analyze(path)
        n = a.numbers
        rows.append({"module": name, "statements": n.n_statements, "missed_statements": n.n_missing,
                     "branches": n.n_branches, "taken": n.n_branches - n.n_missing_branches})
        for line, exits in sorted(a.missing_branch_arcs().items()):
            for e in exits:
                missed.append(f"{name}:{line}->{'exit' if e < 0 else e}")
    # modules never imported by the replay still count: every statement and branch missed
    for p in sorted(root.rglob("*.py")):
        name = str(p.relative_to(root))
        if not any(r["module"] == name for r in rows):
            a = cov._analyze(str(p))
            n = a.numbers
            rows.append({"module": name, "statements": n.n_statements, "missed_statements": n.n_statements,
                         "branches": n.n_branches, "taken": 0})
    rows.sort(key=lambda r: r["module"])
    return rows, missed


def pct(a: int, b: int) -> float:
    return 100.0 * a / b if b else 100.0


def table(rows: list[dict]) -> list[str]:
    out = ["| module | statements | lines % | branches | taken | branches % |", "|---|---:|---:|---:|---:|---:|"]
    for r in rows:
        if not r["branches"] and not r["statements"]:
            continue
        out.append(f"| `{r['module']}` | {r['statements']} | {pct(r['statements'] - r['missed_statements'], r['statements']):.1f} "
                   f"| {r['branches']} | {r['taken']} | {pct(r['taken'], r['branches']):.1f} |")
    s = sum(r["statements"] for r in rows)
    ms = sum(r["missed_statements"] for r in rows)
    b = sum(r["branches"] for r in rows)
    t = sum(r["taken"] for r in rows)
    out.append(f"| **all of port/** | {s} | {pct(s - ms, s):.1f} | {b} | {t} | **{pct(t, b):.1f}** |")
    return out


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--runtime", choices=("coreclr", "mono"), default="coreclr")
    ap.add_argument("--corpus", type=Path, default=None, help="corpus directory (default: the runtime's committed corpus)")
    ap.add_argument("-n", type=int, default=None, help="a stratified sample of N records (default: every record)")
    ap.add_argument("--seed", type=int, default=0)
    ap.add_argument("-j", "--workers", type=int, default=1)
    ap.add_argument("--json", type=Path, default=None)
    ap.add_argument("--missed", type=Path, default=None)
    ap.add_argument("--markdown", type=Path, default=None)
    a = ap.parse_args(argv)
    try:
        import coverage  # noqa: F401
    except ImportError:
        print("corpus_coverage: coverage.py is not installed (pip install coverage)", file=sys.stderr)
        return 2
    cov, n, differing, seconds = measure(a.runtime, a.corpus, a.n, a.seed, max(1, a.workers))
    rows, missed = analyse(cov)
    b = sum(r["branches"] for r in rows)
    t = sum(r["taken"] for r in rows)
    lines = table(rows)
    print("\n".join(lines))
    print(f"{a.runtime}: {n} records replayed in {seconds:.0f} s ({a.workers} workers), {differing} differing; "
          f"branch coverage of port/ {pct(t, b):.1f} % ({t} of {b}); {len(missed)} branches never taken")
    if a.json:
        a.json.write_text(json.dumps({"runtime": a.runtime, "records": n, "differing": differing, "seconds": seconds,
                                      "branches": b, "taken": t, "modules": rows, "missed": missed}, indent=1) + "\n")
    if a.missed:
        a.missed.write_text("".join(m + "\n" for m in missed))
    if a.markdown:
        a.markdown.write_text("\n".join(lines) + "\n")
    return 1 if differing else 0


if __name__ == "__main__":
    sys.exit(main())
