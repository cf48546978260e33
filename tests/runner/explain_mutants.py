"""Print issue 21's figure: for how many planted bugs `explain` names the mutated routine.

    python tests/runner/explain_mutants.py [--runtime coreclr] [--only NAME,...] [--json FILE] [--reuse FILE]

Per planted bug (tests/runner/mutants.py): the first record of the fast lane's corpus sample
(tests/data/corpus/<runtime>/fast-sample.json, in a seeded shuffle, single transitions before tick
scenes) where the mutant differs from
ACE's recorded answer and the port does not, else the first such record of the whole corpus among
the scene kinds the mutant is hunted on (its `kinds`, in the same shuffle; `--sample-only` skips
this); then the mutant run as an external implementation
(tests/impl/planted_impl.py through the protocol, feature `trace`) is traced on that scene, and
acconform.explain names the first divergence from the port's trace. A hit: the routine it names is
the ACE method of the port function holding the mutated text (a mutant in a constant has none).
Each case is also triaged as `check` does (the same implementation, after it ran earlier cases'
scenes and this one untraced): the last line counts the cases where check's group is explain's.
`--reuse FILE` takes each planted bug's killing record (or that none was found) from an earlier run's `--json`
instead of searching again: a record that no longer kills it (the port or the corpus changed) is searched
for anew, as is a planted bug the earlier run did not have.
"""

from __future__ import annotations

import argparse
import ast
import json
import random
import sys
import time
import warnings
from pathlib import Path

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE))


def mutated_routine(m) -> str | None:
    """The ACE method (anchor) of the port function whose body holds the mutation's text."""
    from acconform.port.anchors import load_all
    from mutants import PORT_DIR

    text = (PORT_DIR / m.file).read_text()
    line = text[:text.index(m.old)].count("\n") + 1
    best = None

    def walk(node, prefix):
        nonlocal best
        for ch in ast.iter_child_nodes(node):
            if isinstance(ch, (ast.FunctionDef, ast.ClassDef)):
                q = prefix + ch.name
                if isinstance(ch, ast.FunctionDef) and ch.lineno <= line <= ch.end_lineno:
                    best = q
                walk(ch, q + ".")

    tree = ast.parse(text)
    walk(tree, "")
    module = "acconform.port." + m.file[:-3].replace("/", ".") + "."
    registry = load_all()
    a = registry.get(module + best) if best else None
    if a is None and best is not None and best.startswith("_"):
        # a private helper (e.g. GetBlockOffset's uncached half) is part of the one anchored routine that calls it
        callers = {module + f.name for f in ast.walk(tree) if isinstance(f, ast.FunctionDef) and f.name != best
                   and any(isinstance(n, ast.Name) and n.id == best for n in ast.walk(f))}
        anchored = [registry[c] for c in callers if c in registry]
        a = anchored[0] if len(anchored) == 1 else None
    return a.ace if a else None


def shard_line(where: str) -> str:
    """A corpus entry's `where` ("<shard path> line N") without the shard's folder: a run's --json names a
    record so in any checkout."""
    return Path(where).name


def main() -> int:
    p = argparse.ArgumentParser()
    p.add_argument("--runtime", default="coreclr")
    p.add_argument("--only", default=None)
    p.add_argument("--json", default=None)
    p.add_argument("--sample-only", action="store_true", help="look for a killing record in the fast sample only")
    p.add_argument("--reuse", default=None, metavar="FILE",
                   help="an earlier run's --json: its killing records, instead of searching again")
    args = p.parse_args()
    warnings.simplefilter("ignore")

    from acconform.compare import compare
    from acconform.explain import explain_case, group_name, triage
    from acconform.oracle import default_corpus
    from acconform.oracle.recorded import RecordedOracle
    from acconform.port.run import run_scene
    from acconform.protocol import KINDS, Implementation
    from acconform.runner import Found, guarded, make_case
    from mutants import MUTATIONS, load_mutant

    sample = json.loads((HERE.parent / "data" / "corpus" / args.runtime / "fast-sample.json").read_text())
    keys = {k for k, _, _ in sample["records"]}
    oracle = RecordedOracle(default_corpus())
    everything = oracle.select(runtime=args.runtime)
    random.Random(0).shuffle(everything)
    everything.sort(key=lambda e: e.kind == "ticks")  # single transitions first: a tick scene's trace is tens of them
    in_sample = {id(e) for e in everything if e.key in keys}  # (an entry's key parses its record: once, not per mutant)
    entries = [e for e in everything if id(e) in in_sample]
    only = set(args.only.split(",")) if args.only else None
    earlier = {}
    if args.reuse:
        try:
            earlier = {r["name"]: r for r in json.loads(Path(args.reuse).read_text())}
        except (OSError, ValueError, TypeError, KeyError) as e:
            print(f"explain_mutants: error: --reuse {args.reuse}: not an earlier run's --json ({e})", file=sys.stderr)
            return 2
    by_where = {shard_line(e.where): e for e in everything}
    rows = []
    previous = []  # the killing records so far: the scenes check's implementation would have run before
    for i, m in enumerate(MUTATIONS):
        if only and m.name not in only:
            continue
        t0 = time.monotonic()
        mutant = load_mutant(i)
        rest = [] if args.sample_only else [e for e in everything if id(e) not in in_sample and e.kind in m.kinds]
        rec, where, rec_where = None, None, None

        def kills(e):
            r = oracle._record(e)
            return r if compare(guarded(lambda s: mutant(s, runtime=args.runtime), r.scene), r.outcome, "exact") and \
                not compare(run_scene(r.scene, runtime=args.runtime), r.outcome, "exact") else None

        before = earlier.get(m.name)
        reused = before is not None and (not before["killed"] or (
            shard_line(before["record"] or "") in by_where and kills(by_where[shard_line(before["record"])])))
        if reused and before["killed"]:
            e = by_where[shard_line(before["record"])]
            rec, where, rec_where = oracle._record(e), before["killed_in"], e.where
        for source, candidates in () if reused else (("fast sample", entries), ("corpus", rest)):
            for e in candidates:
                r = kills(e)
                if r is not None:
                    rec, where, rec_where = r, source, e.where
                    break
            if rec is not None:
                break
        row = {"name": m.name, "expected": mutated_routine(m), "killed": rec is not None, "killed_in": where,
               "record": rec_where, **({"reused": True} if reused else {})}
        if rec is not None:
            impl = Implementation(f"{sys.executable} {HERE.parent / 'impl' / 'planted_impl.py'} {m.name} "
                                  f"--kinds {','.join(KINDS)}", timeout=600)
            impl.runtime = args.runtime
            found = [Found(make_case(rec.scene, rec.outcome, rec.outcome, [], 0, "exact", rec.versions), "", [])]
            try:  # as `explain` does: a fresh implementation traces the case
                e = explain_case(found[0].case, impl, "exact", args.runtime, rec.outcome, "ACE's recorded answer")
                # as check's triage does: the implementation has run other scenes, and this one untraced, first
                for other in previous[-3:] + [rec]:
                    guarded(impl, other.scene)
                triage(found, impl, "exact", args.runtime)
            finally:
                impl.close()
            previous.append(rec)
            d = e.divergence
            row.update(routine=d.routine if d else None, field=d.field if d else None, note=e.note,
                       known=e.known.name if e.known else None, hit=bool(d and d.routine == row["expected"]),
                       group=group_name(e), check_agrees=(found[0].group or None) == group_name(e))
        row["seconds"] = round(time.monotonic() - t0, 1)
        rows.append(row)
        print(json.dumps(row), flush=True)
        if args.json:  # after each row: a run stopped early leaves what it found, for --reuse
            Path(args.json).write_text(json.dumps(rows, indent=1))
    named = [r for r in rows if r["killed"] and r["expected"]]
    print(f"explain names the mutated routine for {sum(r['hit'] for r in named)} of {len(named)} planted bugs "
          f"killed by the {args.runtime} corpus whose text lies in an anchored routine "
          f"({len(rows)} run; {sum(not r['killed'] for r in rows)} not killed by it; "
          f"{sum(r['killed'] and not r['expected'] for r in rows)} in a constant)")
    traced = [r for r in rows if r["killed"]]
    print(f"check's triage and explain name the same first divergence for {sum(r['check_agrees'] for r in traced)} "
          f"of {len(traced)} cases")
    return 0


if __name__ == "__main__":
    sys.exit(main())
