"""Print the mutation check's figures: per planted bug, caught or not, scenes to find it, shrunk size.

    python tests/runner/mutation_report.py [-j 2] [--budget 1500] [--seed 0] [--only NAME,...] [--json FILE]

Runs the same hunt as test_mutations.py (mutants.hunt: one worker per mutant, no example
database), mutants spread over -j processes.
"""

from __future__ import annotations

import argparse
import json
import multiprocessing
import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))

from mutants import BUDGET, MUTATIONS, SEED, hunt  # noqa: E402


def _one(args):
    i, budget, seed = args
    return hunt(i, budget, seed)


def main(argv=None) -> int:
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("-j", type=int, default=2)
    p.add_argument("--budget", type=int, default=BUDGET)
    p.add_argument("--seed", type=int, default=SEED)
    p.add_argument("--only", default="")
    p.add_argument("--json", default=None)
    a = p.parse_args(argv)
    names = [m.name for m in MUTATIONS]
    picked = [names.index(n) for n in a.only.split(",") if n] or list(range(len(MUTATIONS)))
    with multiprocessing.get_context("fork").Pool(a.j) as pool:
        rows = []
        for row in pool.imap(_one, [(i, a.budget, a.seed) for i in picked]):
            rows.append(row)
            print(json.dumps(row), flush=True)
    caught = [r for r in rows if r["caught"]]
    print(f"{len(caught)}/{len(rows)} caught")
    print(f"{'mutant':42} {'caught':>6} {'scenes':>6} {'lbs':>4} {'objs':>4} {'path m':>7}")
    for r in rows:
        print(f"{r['name']:42} {'yes' if r['caught'] else 'no':>6} {r['scenes_to_find'] or '-':>6} "
              f"{r.get('landblocks', '-'):>4} {r.get('objects', '-'):>4} {r.get('path', '-'):>7}")
    if a.json:
        Path(a.json).write_text(json.dumps(rows, indent=1))
    return 0


if __name__ == "__main__":
    sys.exit(main())
