"""A campaign's results for CI: a JSON summary (``check --json``) and JUnit XML (``check --junit``).

The JSON summary (``acconform.summary/1``) holds the cases run (compared + skipped), compared
and skipped (by reason), the scenes shrinking ran besides, the differences by field and by scene
kind with their case files (each labelled with how it was shrunk), the seed, versions and timings.
The JUnit file has one testcase per group of differences (their first divergence, routine and field,
where the implementation traces; else the set of differing fields, the runner's signature), each
naming its case files; a clean campaign is one passing testcase.
"""

from __future__ import annotations

import json
import xml.etree.ElementTree as ET
from collections import Counter
from dataclasses import dataclass, field
from pathlib import Path

from . import __version__
from .oracle.recorded import scene_kind
from .runner import Result

SUMMARY_FORMAT = "acconform.summary/1"


@dataclass(slots=True)
class Campaign:
    """What was run, beside the Result: for the reports."""

    source: str  # "live" or "recorded"
    mode: str
    seed: int | None
    kinds: tuple[str, ...]
    implementation: dict  # {"name", "version", "command"}; command "" for the built-in port
    failures_dir: str | None
    bad_records: list[str] = field(default_factory=list)
    kinds_skipped: tuple[str, ...] = ()  # asked for, but the implementation's handshake does not list them


def _classes(result: Result) -> dict[str, list]:
    """The differences by group: their first divergence where the implementation traces (`check`'s
    triage), else the set of fields they differ in."""
    out: dict[str, list] = {}
    for f in result.found:
        out.setdefault(f.group_key, []).append(f)
    return out


def summary(result: Result, c: Campaign) -> dict:
    by_field: Counter = Counter()
    by_kind: Counter = Counter()
    cases = []
    for f in result.found:
        kind = scene_kind(f.case.scene)
        by_kind[kind] += 1
        by_field.update(f.signature)
        sh = f.case.shrink
        cases.append({"file": str(f.path) if f.path else None, "kind": kind, "fields": list(f.signature),
                      "group": f.group_key, "known_divergence": f.known or None,
                      "shrunk": f.shrunk, "shrunk_against": sh.against, "shrink_note": sh.note,
                      "bytes_before": sh.bytes_before or None, "bytes_after": sh.bytes_after or None,
                      "differences": list(f.case.differences)})
    v = result.found[0].case.versions if result.found else result.versions
    t = result.timings
    return {
        "format": SUMMARY_FORMAT,
        "ok": result.ok and not result.interrupted,
        "interrupted": result.interrupted,
        "oracle": c.source,
        "mode": c.mode,
        "seed": c.seed,
        "kinds": list(c.kinds),
        "kinds_skipped": list(c.kinds_skipped),
        "implementation": c.implementation,
        "cases": {"run": result.cases, "compared": result.compared, "skipped": dict(result.skipped),
                  "skipped_total": sum(result.skipped.values()), "shrink_runs": result.shrink_runs,
                  "bad_records": len(c.bad_records)},
        "differences": {"total": len(result.found), "kinds_of_difference": len(_classes(result)),
                        "groups": [{"group": g, "cases": len(fs), "known_divergence": fs[0].known or None,
                                    "kept": str(next((x for x in fs if x.shrunk), fs[0]).path)}
                                   for g, fs in _classes(result).items()],
                        "by_field": dict(sorted(by_field.items())),
                        "by_kind": dict(sorted(by_kind.items())), "cases": cases},
        "failures_dir": c.failures_dir,
        "failures_fallback": result.failures_fallback,
        "versions": {"acconform": __version__, "ace": v.ace if v else "", "runtime": v.runtime if v else ""},
        # the live ACE is not the one the port follows: its differences may be ACE's own (oracle/identity.py)
        "ace_note": result.ace_note,
        "timings": {"elapsed_s": round(result.elapsed, 3),
                    "cases_per_s": round(result.cases / result.elapsed, 1) if result.elapsed > 0 else None,
                    **{f"{k}_s": round(x, 3) for k, x in sorted(t.items())}},
    }


def junit(result: Result, c: Campaign) -> ET.Element:
    classes = _classes(result)
    skipped = sum(result.skipped.values())
    suite = ET.Element("testsuite", name="acconform check", tests=str(max(len(classes), 1) + (1 if skipped else 0)),
                       failures=str(len(classes)), errors="0", skipped=str(1 if skipped else 0),
                       time=f"{result.elapsed:.3f}")
    props = ET.SubElement(suite, "properties")
    for k, val in (("oracle", c.source), ("mode", c.mode), ("seed", "" if c.seed is None else str(c.seed)),
                   ("kinds", ",".join(c.kinds)), ("implementation", c.implementation.get("name", "")),
                   ("cases", str(result.cases)), ("interrupted", str(result.interrupted).lower())):
        ET.SubElement(props, "property", name=k, value=val)
    for group, found in classes.items():
        kinds = sorted({scene_kind(f.case.scene) for f in found})
        known = f" (known: ACE differs from retail here: {found[0].known})" if found[0].known else ""
        tc = ET.SubElement(suite, "testcase", classname=f"acconform.{'+'.join(kinds)}", name=group + known)
        files = [str(f.path) if f.path else "(not written)" for f in found]
        failure = ET.SubElement(tc, "failure", message=f"{len(found)} case{'s' if len(found) != 1 else ''}: "
                                + ", ".join(files), type="difference")
        failure.text = "\n".join(f"{p}\n" + "\n".join(f"  {d}" for d in f.case.differences)
                                 for p, f in zip(files, found))
    if not classes:
        ET.SubElement(suite, "testcase", classname="acconform", name=f"no differences in {result.compared} cases")
    if skipped:
        tc = ET.SubElement(suite, "testcase", classname="acconform", name="scenes the implementation cannot run")
        ET.SubElement(tc, "skipped", message=f"{skipped} skipped: "
                      + ", ".join(f"{why} x{n}" for why, n in result.skipped.most_common()))
    root = ET.Element("testsuites")
    root.append(suite)
    return root


def write_json(path: str | Path, doc: dict) -> None:
    Path(path).write_text(json.dumps(doc, indent=1) + "\n", encoding="utf-8")


def write_junit(path: str | Path, root: ET.Element) -> None:
    ET.indent(root)
    ET.ElementTree(root).write(path, encoding="utf-8", xml_declaration=True)
