"""Arrows leading a moving target onto each arm of ACE's root finders (issue 40; shard ticks-0074).

    python tests/runner/lead_scenes.py OUT_DIR [-n 40] [--seed 74] [--arms A,B]

Creature.GetProjectileVelocity leads a moving target with Trajectory.solve_ballistic_arc's quartic in time
(port/trajectory.py solve_quartic, its resolvent solve_cubic). With the target on flat ground (no vertical
velocity: the quartic's cubic term is 0) the quartic in t is

    c0 t^4 + c2 t^2 + c3 t + c4,   c0 = (g/2)^2, c2 = v^2 - s^2 - g k, c3 = 2 D.v, c4 = |D|^2

(D the aim point less the spawn point, k its height, v the target's CachedVelocity, s the launch speed), so
p = c2/c0, q = c3/c0, r = c4/c0 in Ferrari's normal form. The arms (ARMS), each put by computed numbers:

- ``r0``: the spawn point at the aim point (D = 0): r = 0, the cubic y(y^2 + p y + q) of no absolute term;
- ``triple``: that, with s = |v| (p = 0 too): the cubic's triple root (is_zero(disc), is_zero(q));
- ``double``: the spawn point 1-4 float steps off the aim point along v, s = |v|: a cubic of a double root
  (is_zero(disc), q not 0);
- ``u0``: D across v (q = 0), s > |v|: the resolvent (z - p/2)(z^2 - r) = q^2/8 has the largest root
  z = sqrt(r), so u = z^2 - r is zero;
- ``v0``: D across v, p^2 > 4r (a target faster than the arrow): the largest root z = p/2, so v = 2z - p is zero;
- ``num1``: D across v, p = -2 sqrt(r) (s^2 = v^2 - g k + g |D|: the arrow just reaches the target, a tangent):
  the first quadric's discriminant is zero, one root, and the second quadric is solved twice;
- ``far`` (no solver arm): a 2 cm arrow spawned 22-40 m along its launcher's heading, so IsProjectileVisible's
  transition back to the launcher needs over FindTransitionalPosition's 1,000 steps and is invalid.

Each scene is a drawn moving-target launch (strategies/missiles.py draw_missile_scene's ``fast_target`` arm: a
monster, or the player, walking at 8-30 m/s toward, away from or across the line) made an arrow that leads
(lead_target, no alt_solver) launched at tick 1-5. The port runs it once to read what the launch reads at that
tick (the aim point, the target's CachedVelocity): ACE's and the port's answers agree on them (0 differences), so
the launch's origin and speed are then set to the arm's numbers, refined by float steps until the port's solver
(both runtimes' arithmetic) takes the arm's branch. Every other arrow's Setup carries a MissileFlight placement
(scene/8 `missile_flight`, feature missiles.missile_flight: SetupModel.Unpack's HasMissileFlightPlacement).

Not drawn: v = 2z - p below -1e-9 (no float arithmetic within ACE's reach gives it: tests/data/unreachable-branches.json's
`ace` entry for solve_quartic's `return 0` after v) and Trajectory2's CachedVelocity under EPSILON and not zero (a
creature's velocity under 0.05 m/s is zeroed, UpdatePhysicsInternal, and a target set 1-3 float steps above the
ground is placed onto it by enter_world, and one 1-3 float steps above it at the launch was not found).
"""

from __future__ import annotations

import json
import math
import sys
from dataclasses import replace

import numpy as np

from scene_writer import scene_arguments

ARMS = ("r0", "triple", "double", "u0", "v0", "num1", "far")
WANTED = {"r0": {("trajectory.py", 199, 201)}, "triple": {("trajectory.py", 144, 145)},
          "double": {("trajectory.py", 144, 148)}, "u0": {("trajectory.py", 213, 214)},
          "v0": {("trajectory.py", 220, 221)},
          "num1": {("trajectory.py", 235, 236)}}
G = 9.8


def _arcs_of(fn, *args):
    """(fn's answer, the (file, from line, to line) arcs it takes in port/trajectory.py and trajectory2.py)."""
    import port.trajectory as T
    import port.trajectory2 as T2

    files = {T.__file__, T2.__file__}
    arcs, last = set(), {}

    def local(frame, event, arg):
        if event == "line":
            arcs.add((frame.f_code.co_filename.rsplit("/", 1)[-1], last.get(frame), frame.f_lineno))
            last[frame] = frame.f_lineno
        return local

    def calls(frame, event, arg):
        if frame.f_code.co_filename in files:
            last[frame] = -frame.f_code.co_firstlineno
            return local
        return None

    sys.settrace(calls)
    try:
        answer = fn(*args)
    finally:
        sys.settrace(None)
    return answer, {a for a in arcs if a[1] is not None}


def _f32(x) -> np.float32:
    return np.float32(x)


def _step(x, k: int) -> np.float32:
    """x moved k float32 steps."""
    x = np.float32(x)
    for _ in range(abs(k)):
        x = np.nextafter(x, np.float32(math.inf if k > 0 else -math.inf), dtype=np.float32)
    return x


def _takes(arm: str, origin, dest, speed, velocity) -> bool:
    """Whether the launch's solver takes the arm's branch on both runtimes' arithmetic."""
    from acconform.numerics import MONO, NET10
    from port.missile_launch import get_projectile_velocity

    for runtime in (MONO, NET10):
        _, arcs = _arcs_of(get_projectile_velocity, origin, dest, speed, velocity, True, True, False, runtime)
        if not WANTED[arm] <= arcs:
            return False
    return True


def _solve(arm: str, dest, velocity, speed0, rng):
    """(origin, speed) putting the leading solver on `arm`, from the aim point `dest` and the target's CachedVelocity,
    or None. Computed as the module docstring says, then refined by float steps of the speed and the origin."""
    from acconform.numerics import Vector3

    vx, vy = float(velocity.x), float(velocity.y)
    vt = math.hypot(vx, vy)
    if vt == 0.0:
        return None
    ax, ay = -vy / vt, vx / vt  # across v
    ex, ey, ez = float(dest.x), float(dest.y), float(dest.z)
    side = 1.0 if rng.random() < 0.5 else -1.0
    if arm in ("r0", "triple", "double"):
        origin = [_f32(ex), _f32(ey), _f32(ez)]
        speed = speed0 if arm == "r0" else _f32(math.sqrt(vx * vx + vy * vy))
        if arm == "double":  # 1-4 float steps along v's larger lane
            lane = 0 if abs(vx) >= abs(vy) else 1
            origin[lane] = _step(origin[lane], int(rng.integers(1, 5)) * (1 if rng.random() < 0.5 else -1))
    else:
        length = float(rng.uniform(2.0, 8.0)) if arm != "num1" else float(rng.uniform(0.5, 3.0))
        rise = float(rng.uniform(0.0, 1.5))  # the spawn point above the aim point: k = -rise
        norm = math.hypot(length, rise)
        if arm == "u0":
            s2 = max(float(speed0) ** 2, (vt * 1.5 + 1.0) ** 2)
        elif arm == "v0":
            s2 = (vt * float(rng.uniform(0.2, 0.7))) ** 2  # then p^2 > 4r is checked below
            if (vt * vt - s2 + G * rise) ** 2 <= 4 * (G / 2) ** 2 * norm * norm * 1.1:
                return None
        else:
            s2 = vt * vt + G * rise + G * norm
        if s2 <= 0.25:
            return None
        speed = _f32(math.sqrt(s2))
        origin = [_f32(ex - side * ax * length), _f32(ey - side * ay * length), _f32(ez + rise)]
    if not all(1.0 < float(c) < 191.0 for c in origin[:2]):
        return None
    if arm == "num1":
        return _descend(origin, dest, speed, velocity)
    tries = [(0, 0, 0, 0)] + [tuple(int(k) for k in rng.integers(-40, 41, 4)) for _ in range(200)]
    for ks, kx, ky, kz in tries:
        o = Vector3(_step(origin[0], kx), _step(origin[1], ky), _step(origin[2], kz))
        s = _step(speed, ks)
        if arm in ("r0", "triple"):
            o = Vector3(*origin)
        if _takes(arm, o, dest, s, velocity):
            return o, s
    return None


def _far(scene, i, proj, rng):
    """far: the arrow (a sphere of 2 cm) spawned 22-40 m along its launcher's heading, so IsProjectileVisible's
    transition back to the launcher needs more than Transition.FindTransitionalPosition's 1,000 steps (distance over
    the sphere's radius) and fails: the launch's OnCollideEnvironment and Destroy. Kept when the port's
    is_projectile_visible answers false for that reason (its transition invalid)."""
    import port.missile_launch as ml
    from acconform.numerics import to_f32
    from acconform.scene import SphereRec, validate_scene
    from port.run import run_scene

    launcher = scene.mover if proj.launch.launcher == 0x50000001 else next(o for o in scene.others if o.id == proj.launch.launcher)
    lx, ly, _ = launcher.begin.frame.origin
    ox, oy, oz = proj.launch.origin
    dx, dy = ox - lx, oy - ly
    norm = math.hypot(dx, dy)
    if norm == 0.0:
        return None
    far = float(rng.uniform(22.0, 40.0))
    x, y = lx + dx / norm * far, ly + dy / norm * far
    if not (2.0 < x < 190.0 and 2.0 < y < 190.0):
        return None
    launch = replace(proj.launch, origin=(to_f32(x), to_f32(y), oz))
    made = validate_scene(replace(scene, name=scene.name + ":lead-far", others=scene.others[:i] + (
        replace(proj, launch=launch, spheres=(SphereRec((0.0, 0.0, 0.0), to_f32(0.02)),)),) + scene.others[i + 1:]))
    answers, real_visible = [], ml.is_projectile_visible

    def visible(*args, **kw):
        answers.append(real_visible(*args, **kw))
        return answers[-1]

    ml.is_projectile_visible = visible
    try:
        run_scene(made, runtime="mono")
    finally:
        ml.is_projectile_visible = real_visible
    return made if answers == [False] else None


def _first_quadric_disc(origin, dest, speed, velocity) -> float | None:
    """The discriminant the leading solver's first quadric tests with IsZero (SolveQuadric's), or None when
    solve_quartic returns before it."""
    import port.trajectory as T

    seen = []
    real = T.is_zero

    def noting(d):
        seen.append((sys._getframe(1).f_code.co_name, float(d)))
        return real(d)

    T.is_zero = noting
    try:
        T.solve_ballistic_arc_moving(origin, speed, dest, velocity, np.float32(G))
    finally:
        T.is_zero = real
    quadric = [d for name, d in seen if name == "solve_quadric"]
    return quadric[0] if quadric else None


def _descend(origin, dest, speed, velocity):
    """num1: float steps of the speed and of the origin's lanes across v and up (each moves the first quadric's
    discriminant by about 1e-7; one of the lane along v moves it by far more, through q): for each step of the two
    lanes, the speed's steps that bring the discriminant nearest zero, until it is within IsZero's 1e-9 and the
    solver takes the arm on both runtimes."""
    from acconform.numerics import Vector3

    def disc(ks, k1, k2):
        lanes = [origin[0], origin[1], origin[2]]
        across = 1 if abs(float(velocity.x)) >= abs(float(velocity.y)) else 0
        lanes[across], lanes[2] = _step(lanes[across], k1), _step(lanes[2], k2)
        o, s = Vector3(*lanes), _step(speed, ks)
        return _first_quadric_disc(o, dest, s, velocity), o, s

    for k1 in range(-12, 13):
        for k2 in range(-12, 13):
            d0, _, _ = disc(0, k1, k2)
            d1, _, _ = disc(1, k1, k2)
            if d0 is None or d1 is None or d1 == d0:
                continue
            ks = round(-d0 / (d1 - d0))
            for k in (ks, ks - 1, ks + 1):
                d, o, s = disc(k, k1, k2)
                if d is not None and abs(d) < 1e-9 and _takes("num1", o, dest, s, velocity):
                    return o, s
    return None

def _launch_reads(scene, runtime: str = "mono"):
    """What the scene's launch reads in the port: (origin, aim point, speed, target CachedVelocity), or None."""
    import port.missile_launch as ml
    from port.run import run_scene

    seen = []
    real = ml.get_projectile_velocity

    def reading(origin, dest, speed, velocity, *rest):
        seen.append((origin, dest, speed, velocity))
        return real(origin, dest, speed, velocity, *rest)

    ml.get_projectile_velocity = reading
    try:
        run_scene(scene, runtime=runtime)
    finally:
        ml.get_projectile_velocity = real
    return seen[0] if seen else None


def lead_scene(scene, arm: str, rng):
    """The drawn moving-target scene made an arrow launch on `arm`, or None when its numbers do not serve."""
    from acconform.numerics import to_f32
    from acconform.scene import validate_scene

    i, proj = next((i, o) for i, o in enumerate(scene.others) if o.launch is not None)
    if proj.weenie != "ammunition":
        return None
    if arm == "far":
        return _far(scene, i, proj, rng)
    launch = replace(proj.launch, tick=max(proj.launch.tick, 1), alt_solver=False, lead_target=True)
    others = scene.others[:i] + (replace(proj, launch=launch),) + scene.others[i + 1:]
    base = replace(scene, others=others)
    reads = _launch_reads(base)
    if reads is None:
        return None
    _, dest, speed0, velocity = reads
    solved = _solve(arm, dest, velocity, speed0, rng)
    if solved is None:
        return None
    origin, speed = solved
    launch = replace(launch, origin=tuple(to_f32(float(c)) for c in origin), speed=to_f32(float(speed)))
    others = scene.others[:i] + (replace(proj, launch=launch),) + scene.others[i + 1:]
    made = validate_scene(replace(scene, others=others, name=scene.name + f":lead-{arm}"))
    again = _launch_reads(made)  # the launch reads the same aim point and velocity from the new origin
    if again is None or again[1] != dest or again[3] != velocity:
        return None
    return made


def main(argv=None) -> int:
    from hypothesis import strategies as st

    from acconform.strategies.determinism import pinned_constants
    from acconform.strategies.fast_draw import FastDrawer
    from acconform.strategies.missiles import draw_missile_scene

    ap = scene_arguments(__doc__, n=40, seed=74, n_help="scenes to keep per arm")
    ap.add_argument("--arms", default=",".join(ARMS), help="comma-separated arms (default: every arm)")
    a = ap.parse_args(argv)
    arms = a.arms.split(",")
    unknown = [x for x in arms if x not in ARMS]
    if unknown or a.n < 1:
        print(f"lead_scenes.py: unknown arm {unknown[0]!r} (arms: {', '.join(ARMS)})" if unknown
              else "lead_scenes.py: -n must be a positive count", file=sys.stderr)
        return 2
    a.out.mkdir(parents=True, exist_ok=True)
    rng = np.random.default_rng(a.seed)
    with pinned_constants():
        for arm in arms:
            drawer = FastDrawer(st.composite(lambda d: draw_missile_scene(d, "fast_target"))(),
                                a.seed * 1000003 + ARMS.index(arm))
            kept = drawn = 0
            while kept < a.n and drawn < a.n * 40:
                scene = drawer.draw()[0]
                drawn += 1
                made = lead_scene(scene, arm, rng)
                if made is None:
                    continue
                if kept % 2:  # every other arrow's Setup carries a MissileFlight placement (scene/8 missile_flight)
                    made = replace(made, others=tuple(replace(o, missile_flight=True) if o.launch is not None else o
                                                      for o in made.others), name=made.name + ":missile-flight")
                (a.out / f"s{a.seed}-{arm}-{kept:03d}.json").write_text(json.dumps(made.to_json()))
                kept += 1
            print(f"{arm}: {kept} of {drawn} drawn kept")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
