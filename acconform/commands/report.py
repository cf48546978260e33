"""acconform report DIR --html FILE: an index of a failures directory's cases, grouped by first divergence.

Each case file in DIR (``case-*.json``, as `check` writes them) is explained as `acconform explain`
does (on the implementation it names, against live ACE where configured, else the answer recorded in it) and gets its own page
beside FILE (``FILE``'s name, then the case's); the index lists the cases under their first
divergence (or, where there is no trace, the fields they differ in), each linked to its page.
"""

from __future__ import annotations


def add_arguments(p) -> None:
    p.add_argument("dir", metavar="DIR", help="a failures directory (acconform check --failures)")
    p.add_argument("--html", required=True, metavar="FILE", help="the index page to write")
    p.add_argument("--timeout", type=float, default=60.0, metavar="S",
                   help="seconds an implementation may take for one traced scene (default 60)")
    p.add_argument("--ace", default=None, help="ACE assembly for the live oracle (as `acconform explain`)")
    from . import add_runtime_argument

    add_runtime_argument(p, "the ACE compared with (see `acconform repro`)")


def run(args) -> int:
    from pathlib import Path

    from ..errors import AcconformError
    from ..html import check_writable, explain_page, report_page, write_page
    from ..explain import group_name
    from .explain import explain_case, load_case

    folder = Path(args.dir)
    if not folder.is_dir():
        raise AcconformError(f"{args.dir}: no such directory (give the --failures directory of a check)")
    files = sorted(folder.glob("case-*.json"))
    if not files:
        raise AcconformError(f"{args.dir}: holds no case files (case-*.json)")
    check_writable(args.html)
    index = Path(args.html)
    entries = []
    args.impl = None  # each case on the implementation it names
    for path in files:
        case = load_case(str(path))
        e = explain_case(args, case, case.mode)[0]
        d = e.divergence
        group = (group_name(e) if d is not None
                 else "differs in " + ", ".join(sorted({x.split(':', 1)[0] for x in case.differences})))
        if e.known is not None:
            group += f" (known: ACE differs from retail here: {e.known.name})"
        page = index.with_name(f"{index.stem}-{path.stem}.html")
        write_page(str(page), explain_page(case, e, path.name))
        line = (f"{d.field}: {d.a_value!r} vs {d.b_value!r}" if d is not None else e.note)
        entries.append((group, path.name, page.name, f"{case.scene.name or 'scene'}; {line}"))
    print(f"wrote {write_page(args.html, report_page(f'acconform report: {folder}', entries))} "
          f"({len(files)} cases, {len({g for g, *_ in entries})} groups)")
    return 0
