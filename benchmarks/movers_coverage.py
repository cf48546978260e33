"""Hit rates of the movers strategies (issue 41; kind movers, strategies/movers.py): per 1,000 scenes, what is
drawn (policies, weenies, PlayerKillerStatus pairs, spheres, scales, inputs, clocks, meeting places) and what
the port made of it: collisions between movers (a CollisionTable naming another mover), ticks whose
CollisionTable grew, player pairs exempt from each other (ACE's FindObjCollisions: both players, neither
Free, not both PK, not both PKLite) that passed through each other, and the exact touches' outcomes.

    python benchmarks/movers_coverage.py [-n 1000] [--seed 41]

Scenes come from `sample_scenes(("movers",), n, seed)` and run through the built-in port in process; nothing
is timed. A touch (`touch`: both at rest) "collides" when the other's enter_world does not place it where
it was given (placed elsewhere in x, y, or failed); an approach's "met tick" is the tick at whose end the
walker has walked exactly k steps, where the centre distance is the touch's: ACE's radsum there (the sum
less EPSILON, `<=`) collides at that tick, an ulp short of it one tick later.
"""

from __future__ import annotations

import argparse
import sys
from collections import Counter
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))

MOVER = 0x50000001


def exempt(a: int, b: int) -> bool:
    from acconform.flags import PlayerKillerStatus as P

    return P.Free not in (a, b) and not (a == b == P.PK) and not (a == b == P.PKLite)


def survey(n: int, seed: int) -> Counter:
    from acconform.port.run import run_scene
    from acconform.strategies import sample_scenes

    c = Counter()
    for s in sample_scenes(("movers",), n, seed):
        parts = s.name.split(":")
        pol = parts[1]
        c["policy " + pol] += 1
        c[f"{sum(o.parent is None for o in s.others)} other movers"] += 1
        if pol == "carry":  # carrier, motion, where, the children and how each is held
            c[f"carry: carrier {parts[2]}"] += 1
            c[f"carry: {parts[3].split('-')[0]}"] += 1
            c[f"carry: {parts[4]}"] += 1
            c[f"carry: {parts[5]}hildren"] += 1
            for k in parts[6].split("/"):
                c[f"carry: a child held {k.split('-')[0]}"] += 1
        c["engine mode " + s.engine_mode] += 1
        if pol in ("head_on", "side_on", "chase"):
            c["meeting " + parts[3]] += 1
        bodies = (s.mover,) + s.others
        if any(len(b.spheres) == 2 for b in bodies):
            c["a body of 2 spheres"] += 1
        if any(b.scale != 1.0 for b in bodies):
            c["a scaled body"] += 1
        if "ethereal" in s.name:
            c["an Ethereal turn at a tick"] += 1
        name = s.name
        c["clock " + ("exact grid" if pol == "approach" else "quanta" if "quanta" in name
                      else "irregular" if "irregular" in name else "fps")] += 1
        inputs = {f for t in s.ticks.steps for d in (t,) + tuple(t.others)
                  for f in ("velocity", "local_velocity", "sequence_velocity", "jump") if getattr(d, f) is not None}
        for f in inputs:
            c["input " + f] += 1
        for w in {o.weenie for o in s.others if o.parent is None}:
            c["an other " + w] += 1
        out = run_scene(s)
        if out.error:
            c["scene error"] += 1
            continue
        if any(t.error for t in out.ticks):
            c["a tick ending in ACE's error"] += 1
        for o, placed in zip(s.others, out.other_placements or ()):
            if o.parent is not None:
                c["carry: a child placed " + ("OK" if placed.result == 0 else "GeneralFailure")] += 1
        hit, prev = set(), {}
        for t in out.ticks:
            tables = {MOVER: t.collisions or ()} | {o.id: o.collisions or () for o in (t.others or ())}
            for who, table in tables.items():
                hit.update((who, r.id) for r in table)
                if len(table) > len(prev.get(who, ())):
                    c["ticks whose CollisionTable grew"] += 1
            prev = tables
            c["ticks"] += 1
        ids = {o.id for o in s.others}
        if any(a in ids or b in ids for a, b in hit):
            c["scenes with a collision between movers"] += 1
            c[f"policy {pol}: a collision"] += 1
        for o in (o for o in s.others if o.parent is None):
            met = (MOVER, o.id) in hit or (o.id, MOVER) in hit
            if o.weenie == "player":
                pair = "exempt" if exempt(s.mover.player_killer_status, o.player_killer_status) else "not exempt"
                c[f"mover and a player, {pair}: {'collided' if met else 'passed'}"] += 1
            else:
                c[f"mover and a {o.weenie}: {'collided' if met else 'passed'}"] += 1
        if pol in ("touch", "approach"):
            touch = parts[3] if pol == "approach" else parts[2]
            o = s.others[0]
            if o.weenie == "player" and exempt(s.mover.player_killer_status, o.player_killer_status):
                c[f"{pol} {touch}: exempt pair"] += 1
                continue
            if pol == "touch":
                placed = out.other_placements[0]
                moved = placed.result != 0 or placed.origin[:2] != o.begin.frame.origin[:2]
                c[f"touch {touch}: {'collides at enter_world' if moved else 'placed as given'}"] += 1
            else:
                k = int(parts[6][2:])
                walker_first = parts[2] == "mover"

                def touched(t):
                    table = t.collisions if walker_first else t.others[0].collisions
                    return any(r.id == (o.id if walker_first else MOVER) for r in (table or ()))

                first = next((i for i, t in enumerate(out.ticks) if touched(t)), None)
                when = "never" if first is None else "at" if first == k - 1 else "before" if first < k - 1 else \
                    "one after" if first == k else "later"
                c[f"approach {touch}: first collision {when} the met tick"] += 1
    return c


def main():
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("-n", type=int, default=1000)
    p.add_argument("--seed", type=int, default=41)
    a = p.parse_args()
    c = survey(a.n, a.seed)
    for k in sorted(c):
        print(f"{c[k] * 1000 / a.n:8.0f}  {k}" if k != "ticks" and "CollisionTable" not in k else f"{c[k]:8d}  {k}")


if __name__ == "__main__":
    main()
