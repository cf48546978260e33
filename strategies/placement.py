"""How often drawn scenes put a static where ACE's placement decides what the mover meets.

`placement_table(scenes, outcomes)` counts, per 1,000 scenes, the scenes with a static object
across a cell border, a landblock border or a landblock corner (its reach sphere, shapes.
object_reach, over the line), split by shape (BSP / sphere / cylsphere), size (large: reach
radius 2 m or more), turned or not, and whether the mover starts in the object's own landblock
or a neighbour's; the shapes the validator used to refuse (a leaf root, a radius-0 leaf
sphere); and, from the port's outcomes, the scenes whose static is registered in more than one
cell or more than one landblock (ACE's own-landblock skip leaves a bbox-placed object in one).
benchmarks/bench_strategies.py prints it.
"""

from __future__ import annotations

import math
from collections import Counter

from acconform.scene import BSPLeaf, BSPShape, CylSphereShape, SphereShape

from .shapes import object_reach
from .terrain import BLOCK, CELL

LARGE = 2.0  # metres of reach radius


def _crosses(c: float, r: float, unit: float) -> bool:
    return math.floor((c - r) / unit) != math.floor((c + r) / unit)


def _has_zero_radius_leaf(node) -> bool:
    if isinstance(node, BSPLeaf):
        return node.sphere.radius == 0.0
    return _has_zero_radius_leaf(node.front) or _has_zero_radius_leaf(node.back)


def scene_tags(scene) -> set[str]:
    """The placement situations a scene holds (see the module note)."""
    tags = set()
    for o in scene.objects:
        (cx, cy, _), r = object_reach(o)
        gx = (o.position.cell >> 24) * BLOCK + cx
        gy = ((o.position.cell >> 16) & 0xFF) * BLOCK + cy
        bx, by = _crosses(gx, r, BLOCK), _crosses(gy, r, BLOCK)
        if bx and by:
            border = "landblock corner"
        elif bx or by:
            border = "landblock border"
        elif _crosses(gx, r, CELL) or _crosses(gy, r, CELL):
            border = "cell border"
        else:
            continue
        shape = o.shape
        kind = "setup" if o.setup is not None else "bsp" if isinstance(shape, BSPShape) else "sphere" if isinstance(shape, SphereShape) else "cylsphere"
        assert o.setup is not None or isinstance(shape, (BSPShape, SphereShape, CylSphereShape))
        side = "own" if scene.mover.begin.cell >> 16 == o.position.cell >> 16 else "neighbour"
        tags.add(f"across a {border}")
        tags.add(f"across a {border}: {kind}")
        tags.add(f"across a {border}: {'large' if r >= LARGE else 'small'}")
        if o.position.frame.orientation[0] != 1.0:
            tags.add(f"across a {border}: turned")
        tags.add(f"across a {border}: mover from the {side} landblock")
    for o in scene.objects:
        if isinstance(o.shape, BSPShape):
            if isinstance(o.shape.root, BSPLeaf):
                tags.add("shape: BSP root is a leaf")
            elif _has_zero_radius_leaf(o.shape.root):
                tags.add("shape: a leaf sphere of radius 0")
    return tags


def outcome_tags(outcome) -> set[str]:
    tags = set()
    for cells in outcome.static_cells or ():
        if len(cells) > 1:
            tags.add("registered: in more than one cell")
        if len({c >> 16 for c in cells}) > 1:
            tags.add("registered: in more than one landblock")
    return tags


def placement_table(scenes, outcomes=None) -> list[tuple[str, float]]:
    """(situation, scenes per 1,000) rows, sorted by situation."""
    counts: Counter = Counter()
    for k, s in enumerate(scenes):
        counts.update(scene_tags(s))
        if outcomes is not None:
            counts.update(outcome_tags(outcomes[k]))
    n = max(len(scenes), 1)
    return sorted((tag, 1000.0 * c / n) for tag, c in counts.items())
