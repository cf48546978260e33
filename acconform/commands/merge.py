"""acconform merge: join the parts of a sharded campaign (`check --shard K/N --json`) into one summary.

    acconform merge PART.json... [--json FILE] [--failures DIR]

Every part of one campaign must be given once (the same oracle, mode, seed, kinds, implementation,
runtime, parts and workers). The parts' case files are copied into --failures (a case found by two
parts once; a live campaign keeps one case per kind of difference, the first part's), and the
merged summary is what one unsharded run writes: its counts added, its differences listed once.
Exit 0 when no part found a difference, 1 when one did, 2 (one line) on bad input: a summary that
is missing or not a `check --shard` summary, parts of different campaigns, a part given twice, a
part missing, a case file a summary names that is gone, or an output that cannot be written or
is one of the parts (nothing is written then).
"""

from __future__ import annotations

import shutil
from collections import Counter
from pathlib import Path

# what makes two parts parts of one campaign
SAME = ("oracle", "mode", "seed", "kinds", "implementation")


def add_arguments(p) -> None:
    p.add_argument("summaries", nargs="+", metavar="PART.json", help="the --json summaries of `check --shard K/N`, one per part")
    p.add_argument("--json", default=None, metavar="FILE", help="write the merged JSON summary")
    p.add_argument("--failures", default="failures", metavar="DIR", help="where the parts' case files are copied "
                   "(default ./failures)")


def _load(path: Path) -> dict:
    from .. import deep
    from ..errors import AcconformError
    from ..report import SUMMARY_FORMAT

    try:
        doc = deep.loads(path.read_text())
    except FileNotFoundError:
        raise AcconformError(f"{path}: no such summary") from None
    except (OSError, UnicodeDecodeError) as e:
        raise AcconformError(f"{path}: cannot read it ({getattr(e, 'strerror', None) or e})") from None
    except deep.TooDeep as e:
        raise e.in_file(str(path)) from None
    except ValueError as e:
        raise AcconformError(f"{path}: not JSON ({e})") from None
    if not isinstance(doc, dict) or doc.get("format") != SUMMARY_FORMAT:
        raise AcconformError(f"{path}: not an {SUMMARY_FORMAT} document (the --json of `acconform check`)")
    shard = doc.get("shard")
    if not isinstance(shard, dict) or not all(isinstance(shard.get(k), int) for k in ("part", "parts")):
        raise AcconformError(f"{path}: not the summary of a part (written by `acconform check --shard K/N --json`)")
    for key in ("cases", "differences", "timings"):
        if not isinstance(doc.get(key), dict):
            raise AcconformError(f"{path}: malformed summary: no {key!r} object")
    return doc


def _found(file: str | None, summary: Path) -> str | None:
    """A case file a summary names: a relative one is looked for beside the summary (where `check`
    wrote both, as a CI artifact keeps them), then from here."""
    if not file or Path(file).is_absolute():
        return file
    beside = summary.parent / file
    return str(beside) if beside.is_file() else file


def merge(docs: list[tuple[Path, dict]], failures: Path) -> dict:
    """The merged summary of the parts `docs` ((path, summary) in any order), their case files
    copied into `failures`; AcconformError (one line) on bad input, before anything is written."""
    from ..errors import AcconformError

    first_path, first = docs[0]
    parts = first["shard"]["parts"]
    seen: dict[int, Path] = {}
    for path, doc in docs:
        for key in SAME:
            if doc.get(key) != first.get(key):
                raise AcconformError(f"{path}: not a part of the campaign of {first_path}: its {key} is "
                                     f"{doc.get(key)!r}, not {first.get(key)!r}")
        for key in ("parts", "cases_asked", "workers"):
            if doc["shard"].get(key) != first["shard"].get(key):
                raise AcconformError(f"{path}: not a part of the campaign of {first_path}: its shard {key} is "
                                     f"{doc['shard'].get(key)!r}, not {first['shard'].get(key)!r}")
        if doc.get("versions", {}).get("runtime") != first.get("versions", {}).get("runtime"):
            raise AcconformError(f"{path}: not a part of the campaign of {first_path}: ACE's runtime differs")
        part = doc["shard"]["part"]
        if not 1 <= part <= parts:
            raise AcconformError(f"{path}: malformed summary: part {part} of {parts}")
        if part in seen:
            raise AcconformError(f"parts overlap: part {part}/{parts} is given twice ({seen[part]} and {path})")
        seen[part] = path
    missing = [k for k in range(1, parts + 1) if k not in seen]
    if missing:
        raise AcconformError(f"parts missing: {', '.join(f'{k}/{parts}' for k in missing)} (give every part's summary)")

    live = first["oracle"] == "live"
    cases, kept_files, kept_kinds = [], set(), set()
    for path, doc in sorted(docs, key=lambda d: d[1]["shard"]["part"]):
        for c in doc["differences"].get("cases", []):
            c = dict(c, file=_found(c.get("file"), path))
            name = Path(c["file"]).name if c.get("file") else None
            kind = tuple(c.get("fields", ()))
            if (name is not None and name in kept_files) or (live and kind in kept_kinds):
                continue
            if c.get("file") and not Path(c["file"]).is_file():
                raise AcconformError(f"{path}: its case file {c['file']} is gone (merge the parts where their "
                                     "--failures directories are)")
            kept_files.add(name)
            kept_kinds.add(kind)
            cases.append(c)

    from ..runner import check_writable

    check_writable(failures, "--failures")  # made now, when the parts are known to merge
    merged_cases = []
    for c in cases:
        c = dict(c)
        if c.get("file"):
            target = failures / Path(c["file"]).name
            if Path(c["file"]).resolve() != target.resolve():
                shutil.copyfile(c["file"], target)
            c["file"] = str(target)
        merged_cases.append(c)

    counts = [d["cases"] for _, d in docs]
    skipped: Counter = Counter()
    for c in counts:
        skipped.update(c.get("skipped", {}))
    by_field: Counter = Counter()
    by_kind: Counter = Counter()
    groups: dict[str, list] = {}
    for c in merged_cases:
        by_field.update(c.get("fields", ()))
        by_kind[c.get("kind")] += 1
        groups.setdefault(c.get("group"), []).append(c)
    elapsed = max(d["timings"].get("elapsed_s") or 0.0 for _, d in docs)
    run = sum(c.get("run", 0) for c in counts)
    timings = {"elapsed_s": elapsed, "cases_per_s": round(run / elapsed, 1) if elapsed > 0 else None}
    for k in sorted({k for _, d in docs for k in d["timings"]} - set(timings)):  # worker-seconds: added
        timings[k] = round(sum(d["timings"].get(k) or 0.0 for _, d in docs), 3)
    fallbacks = [d["failures_fallback"] for _, d in docs if d.get("failures_fallback")]
    out = {key: first[key] for key in first if key not in ("shard",)}
    out.update({
        "ok": all(d.get("ok") for _, d in docs) and not merged_cases,
        "interrupted": any(d.get("interrupted") for _, d in docs),
        "cases": {"run": run, "compared": sum(c.get("compared", 0) for c in counts), "skipped": dict(skipped),
                  "skipped_total": sum(skipped.values()), "shrink_runs": sum(c.get("shrink_runs", 0) for c in counts),
                  "bad_records": sum(c.get("bad_records", 0) for c in counts)},
        "differences": {"total": len(merged_cases), "kinds_of_difference": len(groups),
                        "groups": [{"group": g, "cases": len(cs), "known_divergence": cs[0].get("known_divergence"),
                                    "kept": next((x for x in cs if x.get("shrunk")), cs[0]).get("file")}
                                   for g, cs in groups.items()],
                        "by_field": dict(sorted(by_field.items())), "by_kind": dict(sorted(by_kind.items())),
                        "cases": merged_cases},
        "failures_dir": str(failures),
        "failures_fallback": "; ".join(fallbacks) or None,
        "timings": timings,
    })
    return out


def run(args) -> int:
    from ..paths import refuse_output_over_input
    from ..report import write_json
    from ..runner import check_output_file

    refuse_output_over_input(args.json, args.summaries, "--json")
    if args.json is not None:
        check_output_file(args.json, "--json")
    docs = [(Path(p), _load(Path(p))) for p in args.summaries]
    out = merge(docs, Path(args.failures))
    c = out["cases"]
    print(f"merged {len(docs)} parts: {c['run']} cases: {c['compared']} compared, {c['skipped_total']} skipped, "
          f"{out['differences']['total']} difference{'' if out['differences']['total'] == 1 else 's'}")
    for case in out["differences"]["cases"]:
        print(f"  {case.get('file')} ({', '.join(case.get('fields', ()))})")
    if args.json:
        write_json(args.json, out)
    if out["interrupted"]:
        return 130
    return 0 if out["ok"] else 1
