"""Scenes of the recorded corpus changed to take the port's last arcs no record took (issue 24, the
sixth round), for `acconform record`.

    python tests/runner/last_arc_scenes.py OUT_DIR [--only NAMES]

Each variant takes one record of the coreclr corpus, named by its scene key, and changes it:

* `head_beside_over_cylsphere` (bsp-0011, an EdgeSlide mover with two stacked spheres probing past a
  ledge): the second sphere is put beside the first (0.3 m along +y) and the record's cylsphere is
  made 0.1 m wide, under that sphere where the probe looks (its top 0.05 m below the sphere's bottom,
  so the step itself misses it and the probe's 0.125 m drop meets it): CylSphere.IntersectsSphere's
  CheckWalkable arm with the first sphere clear and the second colliding. Stacked spheres cannot do it:
  the probe lowers both alike, and the first would meet the cylsphere in the step first.
* `turn_keeps_sphere_still` (indoor-0000, a two-sphere mover whose head meets a doorway's ceiling):
  the mover moves 0.4 mm west and turns so that its first sphere, 0.2 m off its axis, stays where it
  was: the step is longer than EPSILON, but the first sphere's movement (SlideSphere's gDelta) is
  not, and the head's ceiling normal (anti-parallel to the contact plane's) takes SlideSphere's last
  arm with a gDelta shorter than EPSILON.
* `sphere_near_centre_step_up` (obstacles-0012, a static sphere on the mover's sphere centre, a
  step-up of 5 m): the static moved 5e-5 m off the centre, so StepSphereUp's unnormalised normal is
  tiny but not zero: StepUpSlide hands it to SlideSphere, whose SetCollisionNormal finds it shorter
  than EPSILON (collision_info.py's small collision normal), and ValidateTransition's
  SetSlidingNormal then gets the zeroed normal (the small sliding normal).
* `tiny_sphere_placement` (terrain-0004, a placement that may slide): the mover's sphere is made 1e-4 m
  (below 0.125: FindPlacementPos's fake sphere, 2 / 1e-4 steps of 1e-4 m) and 0.5 m up, with a static
  sphere of 0.5 m overlapping it by 1e-5 m: the placement collides, and the first step's offsets
  (1e-4 m) are shorter than EPSILON, so FindPlacementPos skips them (its vanishing offset) before the
  second step's (2e-4 m) free it.
* `tall_spheres_request_pos` (ticks-0025, a RequestPos mover with an orientation of length 2 in a
  dungeon): the requests' orientation made the identity and the spheres' centres 4 times as high,
  as length 2 makes them on .NET 10: the check position's spheres leave every cell, CheckOtherCells
  leaves no CheckCell, and after the neg-poly step-up fails, StepUpSlide's state makes a next
  insertion, which meets InsertIntoCell with no cell. On mono the length-2 record does not get there.
* `sphere_turned_out_of_world` (ticks-0000, a RequestPos mover outdoors): moved to landblock row 0xFE
  (the world's north edge), one sphere 100 m behind its origin and 50 m up, then three requests at its
  own origin turned 180 degrees: the transitions have no step, so FindTransitionalPosition rebuilds the
  cell array from the sphere, which the first turn took past the world's edge: the second
  SetPositionInternal(Transition) finds the array empty. On .NET 10 only a finite position outside
  the world does that ((int)NaN is 0 there).
* `unnormalized_mover_rising` (ticks-0000, an indoor mover walking into a BSP static): its begin
  orientation doubled (length 2: set_frame makes it the zero quaternion) and 3 m/s upward added to
  every step's velocity. A transition's rotation slerps the zero quaternion into a NaN one; once a
  failed transition's set_initial_frame (which does not validate) has kept that orientation, the next
  tick's AFrame.Combine rotates the tick's movement by it into a NaN origin, the transition carries it
  to SetPositionInternal, and set_frame's AFrame.IsValid meets a NaN origin. Without the upward
  velocity the record reaches no NaN origin.
"""

from __future__ import annotations

import argparse
import json
import math
from pathlib import Path

VARIANT_SHARDS = ("bsp-0015", "indoor-0015", "obstacles-0015", "ticks-0015")  # the shards its scenes were recorded into

SOURCES = {
    "head_beside_over_cylsphere": "6c12c9206cbb647b",
    "turn_keeps_sphere_still": "15b0ddee9fb3fce7",
    "sphere_near_centre_step_up": "cbe0fb389c09e8be",
    "tiny_sphere_placement": "0be70aedd564b21f",
    "tall_spheres_request_pos": "a7634861abc5851b",
    "sphere_turned_out_of_world": "50b1a9e3f4fd3a5d",
    "unnormalized_mover_rising": "7df48c6f7a2a99c6",
}


def _f32(v: float) -> float:
    from acconform.numerics import to_f32

    return float(to_f32(v))


def head_beside_over_cylsphere(doc: dict) -> dict:
    """See the module docstring. The probe's check position is measured by the port on the record
    itself (the first CheckWalkable call); the first sphere's path does not change."""
    from acconform.port.run import run_scene
    from acconform.port.transition import transition as T
    from acconform.scene import Scene

    seen = []
    check_walkable = T.Transition.check_walkable

    def measured(self, z):
        seen.append(self.sphere_path.global_sphere[0].center)
        return check_walkable(self, z)

    T.Transition.check_walkable = measured  # this process only: a measurement
    try:
        run_scene(Scene.from_json(doc), runtime="coreclr")
    finally:
        T.Transition.check_walkable = check_walkable
    c = seen[0]
    s = json.loads(json.dumps(doc))
    low = s["mover"]["spheres"][0]
    r = low["radius"]
    s["mover"]["spheres"][1] = {"center": [0.0, 0.3, low["center"][2]], "radius": r}
    cyl = next(o for o in s["objects"] if o["shape"]["kind"] == "cylsphere")
    height = 0.2
    cyl["shape"] = {"kind": "cylsphere", "low_point": [0.0, 0.0, 0.0], "radius": 0.1, "height": height}
    # sphere 1 beside sphere 0 at the probe's check position; the cylsphere's top 0.05 m under its bottom
    cyl["position"]["origin"] = [_f32(float(c.x)), _f32(float(c.y) + 0.3), _f32(float(c.z) - r - 0.05 - height)]
    return s


def turn_keeps_sphere_still(doc: dict) -> dict:
    """See the module docstring: begin 57.8 m east (under the doorway's lintel), 4e-4 m west, the
    first sphere 0.2 m to the mover's left, the end heading turned by -asin(4e-4 / 0.2)."""
    s = json.loads(json.dumps(doc))
    m = s["mover"]
    length, off = 4e-4, 0.2
    m["begin"]["origin"][0] = 57.8
    b = m["begin"]["origin"]
    m["end"] = json.loads(json.dumps(m["begin"]))
    m["end"]["origin"] = [_f32(b[0] - length), b[1], b[2]]
    m["spheres"][0]["center"] = [0.0, off, m["spheres"][0]["center"][2]]
    theta = -math.asin(length / off)
    m["end"]["orientation"] = [_f32(math.cos(theta / 2)), 0.0, 0.0, _f32(math.sin(theta / 2))]
    return s


def sphere_near_centre_step_up(doc: dict) -> dict:
    s = json.loads(json.dumps(doc))
    o = s["objects"][-1]["position"]["origin"]
    s["objects"][-1]["position"]["origin"] = [_f32(o[0] + 5e-5), o[1], o[2]]
    return s


def tiny_sphere_placement(doc: dict) -> dict:
    s = json.loads(json.dumps(doc))
    m = s["mover"]
    r, big, overlap = 1e-4, 0.5, 1e-5
    m["spheres"] = [{"center": [0.0, 0.0, 0.5], "radius": r}]
    b = m["begin"]["origin"]
    dist = big + r - 2e-4 - overlap  # radsum (r + big - EPSILON) less the overlap
    s["objects"] = [{"id": "0x72000000", "position": {"cell": m["begin"]["cell"], "origin": [_f32(b[0] + dist), b[1], _f32(b[2] + 0.5)],
                                                     "orientation": [1.0, 0.0, 0.0, 0.0]},
                     "shape": {"kind": "sphere", "center": [0.0, 0.0, 0.0], "radius": big}, "state": ["Static"]}]
    return s


def tall_spheres_request_pos(doc: dict) -> dict:
    s = json.loads(json.dumps(doc))
    for sp in s["mover"]["spheres"]:
        sp["center"] = [0.0, 0.0, _f32(sp["center"][2] * 4.0)]
    for st in s["ticks"]["steps"]:
        st["request_pos"]["orientation"] = [1.0, 0.0, 0.0, 0.0]
    return s


def sphere_turned_out_of_world(doc: dict) -> dict:
    block = doc["mover"]["begin"]["cell"][:6]  # "0xXXYY"
    s = json.loads(json.dumps(doc).replace(block, block[:4] + "FE"))
    m = s["mover"]
    m["spheres"] = [{"center": [0.0, -100.0, 50.0], "radius": m["spheres"][0]["radius"]}]
    b = m["begin"]
    s["ticks"]["steps"] = [{"dt": s["ticks"]["steps"][0]["dt"],
                            "request_pos": {"cell": b["cell"], "origin": b["origin"], "orientation": [0.0, 0.0, 0.0, 1.0]}}
                           for _ in range(3)]
    return s


def unnormalized_mover_rising(doc: dict) -> dict:
    s = json.loads(json.dumps(doc))
    m = s["mover"]
    m["begin"]["orientation"] = [2.0 * v for v in m["begin"]["orientation"]]
    for st in s["ticks"]["steps"]:
        v = st.get("velocity") or [0.0, 0.0, 0.0]
        st["velocity"] = [v[0], v[1], 3.0]
    return s


VARIANTS = [head_beside_over_cylsphere, turn_keeps_sphere_still, sphere_near_centre_step_up, tiny_sphere_placement,
            tall_spheres_request_pos, sphere_turned_out_of_world, unnormalized_mover_rising]


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("out", type=Path)
    ap.add_argument("--only", default=None, help="comma-separated variant names to write")
    a = ap.parse_args(argv)
    a.out.mkdir(parents=True, exist_ok=True)

    from acconform.oracle import default_corpus
    from acconform.oracle.recorded import RecordedOracle
    from acconform.scene import Scene

    only = set(a.only.split(",")) if a.only else None
    oracle = RecordedOracle(default_corpus("coreclr"))
    docs = {}
    for e in oracle.entries:
        for name, key in SOURCES.items():
            if e.key.startswith(key):
                docs[name] = e.doc()["scene"]
    written = 0
    for make in VARIANTS:
        name = make.__name__
        if only is not None and name not in only:
            continue
        doc = make(docs[name])
        doc["name"] = f"{docs[name]['name']}:{name}"
        Scene.from_json(doc)  # refuses a malformed scene here, not in record
        (a.out / f"{SOURCES[name]}-{name}.json").write_text(json.dumps(doc))
        written += 1
    print(f"{written} scenes in {a.out}")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
