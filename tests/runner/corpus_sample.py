"""The fast lane's fixed, stratified sample of the recorded corpus.

    python tests/runner/corpus_sample.py [--size 1500] [--runtime mono|coreclr]
        rebuild tests/data/corpus/<runtime>/fast-sample.json (default: both runtimes' samples)
    python tests/runner/corpus_sample.py --add SHARD... [--runtime mono|coreclr]
        add a new recording's shards to the samples, running only their records
    python tests/runner/corpus_sample.py --replace SHARD... --old DIR [--runtime mono|coreclr]
        shards re-recorded in place (the old ones in DIR/<runtime>/): only their old and new records run

Runs every record of a runtime's corpus through the port (computing as that runtime does) with a
branch trace, then picks, deterministically
(by scene key): for each branch, rarest first, up to PER_BRANCH records that fire it; then
records spread evenly over the kinds until SIZE. The file lists each picked record's key, kind
and the branches it fires, plus how many corpus records fire each branch, so a test can check
that the sample reaches every kind and every branch the whole corpus reaches without running
the whole corpus (the full replay is the slow lane and `acconform check`).
"""

from __future__ import annotations

import argparse
import json
import sys
import warnings
from collections import Counter, defaultdict
from pathlib import Path

SAMPLE_NAME = "fast-sample.json"  # beside the corpus it samples: tests/data/corpus/<runtime>/fast-sample.json
SIZE = 1500
PER_BRANCH = 25


def sample_file(runtime: str) -> Path:
    from acconform.oracle import default_corpus

    return default_corpus(runtime) / SAMPLE_NAME


def load_sample(runtime: str) -> dict:
    return json.loads(sample_file(runtime).read_text())


BORDERS = {"boundary:cell_border", "boundary:landblock_border"}


def _fires(corpus_dir, wanted=lambda where: True) -> dict[str, tuple[str, frozenset]]:
    """{scene key: (kind, the branches its port run fires)} for the corpus's records whose
    "SHARD line N" `wanted` accepts, each run computing as the corpus's runtime does."""
    from acconform.numerics import runtime_named
    from acconform.oracle.recorded import RecordedOracle, scene_kind
    from acconform.port.run import run_scene
    from acconform.scene import Scene

    warnings.simplefilter("ignore", RuntimeWarning)
    oracle = RecordedOracle(corpus_dir)
    runtime = runtime_named(oracle.versions.runtime)
    fires: dict[str, tuple[str, frozenset]] = {}
    for key, entry in sorted(oracle.index().items()):
        if not wanted(entry.where):
            continue
        scene = Scene.from_json(entry.doc()["scene"])
        trace: Counter = Counter()
        run_scene(scene, trace=trace, runtime=runtime)
        fires[key] = (scene_kind(scene), frozenset(trace))
    return fires


def _boundary_records(fires) -> int:
    # records whose port run hits an exact boundary other than a cell or landblock border
    # (branches.BOUNDARIES; `acconform record --boundaries` keeps only those)
    return sum(any(b.startswith("boundary:") and b not in BORDERS for b in branches) for _, branches in fires.values())


def build(corpus_dir, size: int = SIZE, per_branch: int = PER_BRANCH) -> dict:
    fires = _fires(corpus_dir)
    by_branch: dict[str, list[str]] = defaultdict(list)
    for key, (_, branches) in fires.items():
        for b in branches:
            by_branch[b].append(key)
    picked: dict[str, None] = {}
    for b in sorted(by_branch, key=lambda b: (len(by_branch[b]), b)):
        for key in by_branch[b][:per_branch]:
            picked[key] = None
    by_kind: dict[str, list[str]] = defaultdict(list)
    for key, (kind, _) in fires.items():
        if key not in picked:
            by_kind[kind].append(key)
    kinds = sorted(by_kind)
    i = 0
    while len(picked) < size and any(by_kind.values()):
        k = kinds[i % len(kinds)]
        if by_kind[k]:
            picked[by_kind[k].pop(0)] = None
        i += 1
    names = sorted(by_branch)
    return {
        "made_by": "python tests/runner/corpus_sample.py",
        "corpus_records": len(fires),
        "boundary_records": _boundary_records(fires),
        "corpus_branches": {b: len(by_branch[b]) for b in names},
        "branches": names,
        "records": [[key, fires[key][0], sorted(names.index(b) for b in fires[key][1])] for key in picked],
    }


def add(doc: dict, corpus_dir, shard_names, per_branch: int = PER_BRANCH, per_kind: int = 100) -> dict:
    """`doc` (a runtime's sample) with the records of the corpus shards `shard_names` added, running
    only those through the port: each branch's corpus count grows by the new records that fire it, a
    branch fired by fewer than `per_branch` sample records gets new ones (rarest first), and each new
    kind gets up to `per_kind` more, spread as `build` spreads them. What a new recording needs,
    without the hour a rebuild takes; a rebuild (`build`) picks afresh from the whole corpus."""
    names = set(shard_names)
    fires = _fires(corpus_dir, lambda where: Path(where.rsplit(" line ", 1)[0]).name.split(".")[0] in names)
    new = _add_fires(doc, fires, per_branch, per_kind)
    new["made_by"] = f"{doc['made_by']}, then --add {' '.join(sorted(names))}"
    return new


def _add_fires(doc: dict, fires: dict, per_branch: int, per_kind: int) -> dict:
    """`doc` with the records of `fires` ({key: (kind, branches)}) counted and picked as `add` says."""
    old_names = doc["branches"]
    records = {key: (kind, frozenset(old_names[i] for i in idx)) for key, kind, idx in doc["records"]}
    if records.keys() & fires.keys():
        raise SystemExit("the sample already holds records of those shards: rebuild it instead")
    counts = Counter(doc["corpus_branches"])
    in_sample = Counter(b for _, branches in records.values() for b in branches)
    by_branch: dict[str, list[str]] = defaultdict(list)
    for key, (_, branches) in fires.items():
        for b in branches:
            counts[b] += 1
            by_branch[b].append(key)
    for b in sorted(by_branch, key=lambda b: (counts[b], b)):
        for key in by_branch[b]:
            if in_sample[b] >= per_branch:
                break
            if key not in records:
                records[key] = fires[key]
                in_sample.update(fires[key][1])
    by_kind: dict[str, list[str]] = defaultdict(list)
    for key, (kind, _) in fires.items():
        if key not in records:
            by_kind[kind].append(key)
    for kind, keys in sorted(by_kind.items()):
        have = sum(1 for k, _ in records.values() if k == kind)
        for key in keys[: max(0, per_kind - have)]:
            records[key] = fires[key]
    branches = sorted(counts)
    return {
        **doc,
        "corpus_records": doc["corpus_records"] + len(fires),
        "boundary_records": doc["boundary_records"] + _boundary_records(fires),
        "corpus_branches": {b: counts[b] for b in branches},
        "branches": branches,
        "records": [[key, kind, sorted(branches.index(b) for b in br)] for key, (kind, br) in records.items()],
    }


def replace(doc: dict, corpus_dir, old_dir, shard_names, per_branch: int = PER_BRANCH, per_kind: int = 100) -> dict:
    """`doc` with the shards `shard_names` re-recorded in place (their old versions in `old_dir`): the old
    records' branch counts come out (running them through the port), the sample's records that are no longer
    in the corpus go, and the new records go in as `add` adds a new recording's. Without the hour a rebuild
    takes, for a re-recording that changes some scenes of some shards (issue 44's server-mode ticks)."""
    names = set(shard_names)
    in_shards = lambda where: Path(where.rsplit(" line ", 1)[0]).name.split(".")[0] in names  # noqa: E731
    old = _fires(old_dir, in_shards)
    fires = _fires(corpus_dir, in_shards)
    counts = Counter(doc["corpus_branches"])
    for _, branches in old.values():
        counts.subtract(branches)
    old_names = doc["branches"]
    kept = [r for r in doc["records"] if r[0] not in old or r[0] in fires]
    kept_doc = {**doc, "records": [r for r in kept if r[0] not in fires],
                "corpus_records": doc["corpus_records"] - len(old),
                "boundary_records": doc["boundary_records"] - _boundary_records(old),
                "corpus_branches": {b: n for b, n in counts.items() if n > 0}}
    kept_doc["branches"] = sorted(kept_doc["corpus_branches"])
    kept_doc["records"] = [[key, kind, sorted(kept_doc["branches"].index(old_names[i]) for i in idx
                                              if old_names[i] in kept_doc["corpus_branches"])]
                           for key, kind, idx in kept_doc["records"]]
    new = _add_fires(kept_doc, fires, per_branch, per_kind)
    new["made_by"] = f"{doc['made_by']}, then --replace {' '.join(sorted(names))}"
    return new


def main(argv=None) -> int:
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("--size", type=int, default=SIZE)
    p.add_argument("--runtime", choices=("mono", "coreclr"), action="append",
                   help="the runtime whose corpus to sample (repeatable; default both)")
    p.add_argument("--add", nargs="+", metavar="SHARD", help="add the records of these shards (names such as "
                   "ticks-0000) to the existing sample, running only them through the port")
    p.add_argument("--replace", nargs="+", metavar="SHARD", help="these shards were re-recorded in place: take "
                   "their old records (in --old DIR/<runtime>) out of the sample's counts and add the new ones")
    p.add_argument("--old", metavar="DIR", help="with --replace: a folder holding <runtime>/ with the old shards")
    args = p.parse_args(argv)
    from acconform.oracle import default_corpus

    for runtime in args.runtime or ("coreclr", "mono"):
        if args.replace:
            doc = replace(load_sample(runtime), default_corpus(runtime), Path(args.old) / runtime, args.replace)
        elif args.add:
            doc = add(load_sample(runtime), default_corpus(runtime), args.add)
        else:
            doc = build(default_corpus(runtime), args.size)
        sample_file(runtime).write_text(json.dumps(doc, separators=(",", ":")) + "\n")
        kinds = Counter(r[1] for r in doc["records"])
        print(f"{len(doc['records'])} of {doc['corpus_records']} records ({dict(kinds)}; "
              f"{doc['boundary_records']} corpus records hit an exact boundary), "
              f"{len(doc['branches'])} branches -> {sample_file(runtime)}", file=sys.stderr)
    return 0


if __name__ == "__main__":
    sys.exit(main())
