"""Placements: a share of drawn scenes of every kind has its mover placed by ACE's PhysicsObj.SetPosition.

`with_placement(draw, scene)` gives the scene a ``mover.placement`` about one time in four (and
engine mode client, which ACE's placement of a scene's mover needs). The begin position is then
biased toward where placement goes wrong:

- "as drawn": the begin position as the scene drew it (the cell holds the point);
- "at end": the end position (a wall, a ledge, an object the path ran into), so the placement
  overlaps geometry and FindValidPosition pushes the mover out -- by less or more than 0.05 in x
  or y, toward + or - (CheckPositionInternal's comparison has no Math.Abs);
- "backed off": the end position backed off toward the begin a little (a few centimetres to a third
  of a metre): overlaps small and large;
- "other cell": the point kept, the cell id another cell of its landblock: indoors another
  EnvCell (find_visible_child_cell finds the point's cell among its visible cells, or not; a
  SeenOutside cell falls out to the landblock), outdoors another land cell (AdjustToOutside
  fixes it);
- "nowhere": the point moved well away from its cell (into no EnvCell, or off the dungeon), half the
  time under a SeenOutside cell's id when the dungeon has one (AdjustPosition's adjust_to_outside);
- "bad id": a cell id outside AdjustPosition's ranges (0, 0x41..0xFF, 0xFFFE).

Flags: Slide or not (the 0.05 check runs only without it), sometimes DontCreateCells and the flags
ACE ignores here (Placement, Teleport, SendPositionEvent); get_cell true or false.
`placement_table(scenes)` counts the draws per 1,000 scenes (benchmarks/bench_strategies.py).
"""

from __future__ import annotations

from collections import Counter
from dataclasses import replace

from hypothesis import strategies as st

from acconform.flags import SetPositionFlags
from acconform.numerics import to_f32
from acconform.scene import ENV_CELL_FIRST, Frame, Placement, Position, Scene

from . import draws as dr

PLACE = st.sampled_from((False, False, False, True))
WHERE = st.sampled_from(("as drawn", "at end", "at end", "backed off", "backed off", "other cell", "other cell",
                         "nowhere", "nowhere", "bad id"))
NUDGES = dr.OneOf(dr.f32(0.0, 0.06), dr.f32(0.0, 0.35))
SLIDE = st.sampled_from((False, True))
GET_CELL = st.sampled_from((False, True))
EXTRA_FLAGS = st.sampled_from((0, 0, int(SetPositionFlags.Placement), int(SetPositionFlags.Teleport),
                               int(SetPositionFlags.DontCreateCells),
                               int(SetPositionFlags.Placement | SetPositionFlags.SendPositionEvent)))
BAD_IDS = st.sampled_from((0x0000, 0x0041, 0x00FF, 0xFFFE))
AWAY = st.sampled_from(((0.0, 0.0, 30.0), (40.0, 0.0, 0.0), (0.0, -40.0, 0.0), (0.0, 0.0, -8.0)))
OTHER = dr.ints(0, 1 << 16)


def _landblock_defined(scene: Scene, cell: int) -> bool:
    return any(lb.id >> 16 == cell >> 16 for lb in scene.landblocks)


def with_placement(draw, scene: Scene) -> Scene:
    """The scene, or (one time in four) the scene with its mover placed by ACE (see the module)."""
    if not draw(PLACE):
        return scene
    m = scene.mover
    where = draw(WHERE)
    begin = m.begin
    block = begin.cell & 0xFFFF0000
    if where == "at end" and _landblock_defined(scene, m.end.cell):
        begin = Position(m.end.cell, Frame(m.end.frame.origin, begin.frame.orientation))
    elif where == "backed off" and _landblock_defined(scene, m.end.cell):
        dx, dy = (b - e for b, e in zip(begin.frame.origin[:2], m.end.frame.origin[:2]))
        length = (dx * dx + dy * dy) ** 0.5
        x, y, z = m.end.frame.origin
        if length > 0:
            step = dr.take(draw, NUDGES)
            x, y = to_f32(x + dx / length * step), to_f32(y + dy / length * step)
        begin = Position(m.end.cell, Frame((x, y, z), begin.frame.orientation))
    elif where == "other cell":
        if scene.env_cells:
            cells = [c.id for c in scene.env_cells if c.id >> 16 == begin.cell >> 16]
            cell = cells[draw(OTHER) % len(cells)] if cells else begin.cell
        else:
            cell = block | (1 + draw(OTHER) % 64)
        begin = Position(cell, begin.frame)
    elif where == "nowhere":
        ax, ay, az = draw(AWAY)
        x, y, z = begin.frame.origin
        seen_outside = [c.id for c in scene.env_cells if c.seen_outside and c.id >> 16 == begin.cell >> 16]
        cell = seen_outside[draw(OTHER) % len(seen_outside)] if seen_outside and draw(dr.BOOLEANS) else begin.cell
        begin = Position(cell, Frame((to_f32(x + ax), to_f32(y + ay), to_f32(z + az)), begin.frame.orientation))
    elif where == "bad id":
        begin = Position(block | draw(BAD_IDS), begin.frame)
    flags = draw(EXTRA_FLAGS) | (int(SetPositionFlags.Slide) if draw(SLIDE) else 0)
    placement = Placement(flags, draw(GET_CELL))
    return replace(scene, engine_mode="client", mover=replace(m, begin=begin, placement=placement))


def placement_table(scenes) -> dict[str, float]:
    """Per 1,000 scenes: those with a placement, by Slide, get_cell, and an indoor or outdoor begin cell id."""
    scenes = list(scenes)
    counts: Counter = Counter()
    for s in scenes:
        p = s.mover.placement
        if p is None:
            continue
        counts["placed"] += 1
        counts["placed, Slide" if p.flags & SetPositionFlags.Slide else "placed, no Slide"] += 1
        counts["placed, get_cell" if p.get_cell else "placed, cell as given"] += 1
        low = s.mover.begin.cell & 0xFFFF
        counts["placed, EnvCell id" if low >= ENV_CELL_FIRST and low != 0xFFFE else
               "placed, land cell id" if 1 <= low <= 64 else "placed, id out of AdjustPosition's ranges"] += 1
    n = max(len(scenes), 1)
    return {k: 1000.0 * v / n for k, v in sorted(counts.items())}
