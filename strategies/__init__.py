"""acconform.strategies: Hypothesis strategies that build valid scenes by construction.

    scenes(kinds=("terrain",))      a strategy of acconform.scene.Scene
    sample_scenes(kinds, n, seed)   n scenes, the same ones for the same seed (used by `record`)

Kinds: "terrain" (a mover over generated terrain), "bsp" (BSP objects on mostly level ground:
ledges to walk off, stairs to climb, walls and corners to slide along, statics straddling cell and
landblock borders and corners (BSP, sphere, cylsphere; leaf-root and radius-0-leaf trees too) --
strategies/objects.py; strategies/placement.py counts them per 1,000 scenes --
or walls, floors, ramps, steps, platforms, posts, boxes, convex polygons scattered along a path), "obstacles"
(spheres and cylspheres), "indoor" (dungeons of EnvCells joined by portals -- rooms, corridors,
T-junctions, ramps at and around FloorZ, stairs, ledges, pits, narrow doorways, seams, turned cell
frames, statics inside and across cells, portals to outside -- strategies/dungeon.py), "buildings" (a house shell on terrain over EnvCells
entered through the building's portal: doors barely wider than the mover, in and out, along the
walls, porches, cellars, borders, a static in the doorway, placements inside -- strategies/buildings.py), "ticks"
(any of those worlds with a timeline of ticks: falls, jumps, slides, sledding, presses, crossings,
portals, quantum-exact clocks, threshold velocities, both drivers -- strategies/ticks.py), "motion",
"doors" and "movers" (tick scenes of one ticks policy: strategies/motion.py, doors.py, movers.py), "missiles"
(a projectile launched at a tick: strategies/missiles.py), "targets" (a MoveTo, sticky follow, turn or stick_to
at another mover: strategies/motion.py draw_managed_chase), and
"ticks:<world>" (tick scenes over that world only, e.g. "ticks:buildings": through a house's door,
off its porch, down its cellar, along its shell; recorded as "ticks"). DEFAULT_KINDS
is what the port supports today; grow it as the port does. Every float in a drawn scene is an exact float32, so its JSON round trip is exact.
"""

from __future__ import annotations

from typing import Iterator

from hypothesis import strategies as st

from acconform.errors import AcconformError

from .draws import OneOf
from .scenes import scenes_of

from acconform.protocol import CAMPAIGN_KINDS as ALL_KINDS
from acconform.protocol import KINDS as GEOMETRY_KINDS

# The kinds a campaign draws (and a corpus replay runs) when --kinds is not given: what the port
# supports, all of them since the port went indoors (issue 12) and ticked (issue 19): a sixth of a
# live campaign's scenes are tick scenes, and a replay runs the ticks shards with the others.
DEFAULT_KINDS: tuple[str, ...] = ALL_KINDS


# "ticks:<world>": tick scenes over one world (a geometry kind)
TICK_WORLD_KINDS: tuple[str, ...] = tuple(f"ticks:{k}" for k in GEOMETRY_KINDS)
# "motion": tick scenes of the ticks policy motion only (strategies/motion.py: motion tables, MoveToState keys,
# the server's MoveTo / turn / stop / DoMotion calls); recorded as "ticks"; an implementation runs it when it
# lists "ticks" and the feature mover.motion (protocol.Implementation.kinds; the built-in port does)
MOTION_KIND = "motion"
# "doors": tick scenes of the ticks policy door only (strategies/doors.py: a door on the path opens or closes at a
# tick); recorded as "ticks"; an implementation runs it when it lists "ticks" and the feature doors
DOORS_KIND = "doors"
# "missiles": tick scenes of a projectile launched at a tick (strategies/missiles.py); recorded as "ticks"; an
# implementation runs it when it lists "ticks" and the features objects.moving and missiles
MISSILES_KIND = "missiles"
# "movers": tick scenes of the ticks policy movers only (strategies/movers.py: one to three other moving objects
# beside the mover -- head-on, side-on, at corners, chasing, exactly touching, jumping over); recorded as "ticks";
# an implementation runs it when it lists "ticks" and the feature objects.moving
MOVERS_KIND = "movers"
# "targets": tick scenes of the server's MoveToObject, sticky MoveToObject, TurnToObject or a melee swing's
# stick_to at another mover that walks, stops or is destroyed (strategies/motion.py draw_managed_chase: the
# managers, MoveToManager, StickyManager, TargetManager's voyeurs); recorded as "ticks"; an implementation runs
# it when it lists "ticks" and the features mover.motion, objects.moving and objects.targets
TARGETS_KIND = "targets"
EXTRA_KINDS: tuple[str, ...] = (MOTION_KIND, DOORS_KIND, MOVERS_KIND, MISSILES_KIND, TARGETS_KIND)  # tick scenes of one policy


def kind_supported(kind: str, supported) -> bool:
    """Whether a campaign kind is among an implementation's `supported` campaign kinds: "ticks:<world>"
    when it lists "ticks" and the world."""
    base, _, world = kind.partition(":")
    return base in supported and (not world or world in supported)


def check_kinds(kinds) -> tuple[str, ...]:
    if kinds is None:
        return DEFAULT_KINDS
    given = kinds
    if isinstance(kinds, str):
        kinds = tuple(k.strip() for k in kinds.split(","))
    kinds = tuple(kinds)
    if not kinds or kinds == ("",):
        raise AcconformError(f"no scene kinds chosen (known: {', '.join(ALL_KINDS)})")
    for k in kinds:
        if not k:
            raise AcconformError(f"--kinds {given!r}: an empty kind name between commas "
                                 f"(known: {', '.join(ALL_KINDS)})")
        if k not in ALL_KINDS and k not in TICK_WORLD_KINDS and k not in EXTRA_KINDS:
            raise AcconformError(f"unknown scene kind {k!r} (known: {', '.join(ALL_KINDS + EXTRA_KINDS)}, or ticks:<world> for "
                                 f"tick scenes over one of {', '.join(GEOMETRY_KINDS)})")
    if len(set(kinds)) != len(kinds):
        twice = next(k for k in kinds if kinds.count(k) > 1)
        raise AcconformError(f"--kinds {given!r}: {twice!r} is named twice")
    return kinds


def scenes(kinds=None) -> st.SearchStrategy:
    """Scenes of the given kinds (default DEFAULT_KINDS), drawn evenly across kinds."""
    kinds = check_kinds(kinds)
    if len(kinds) == 1:
        return scenes_of(kinds[0])
    return OneOf(*(scenes_of(k) for k in kinds)).strategy  # st.one_of's draw, built once


def sample_scenes(kinds: tuple[str, ...] | None, n: int, seed: int) -> Iterator:
    """n scenes drawn from scenes(kinds), deterministic for a seed (and a Hypothesis version).

    Drawn as a campaign draws its fresh scenes (strategies.fast_draw: the strategies, with Hypothesis'
    own choice distribution, from a Random seeded by `seed`), so sampled scenes have the
    distribution a campaign explores.
    """
    from .determinism import pinned_constants
    from .fast_draw import FastDrawer

    drawer = FastDrawer(scenes(kinds), seed * 1000003)
    with pinned_constants():
        out = [drawer.draw()[0] for _ in range(n)]
    yield from out
