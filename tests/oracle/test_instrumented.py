"""The instrumented ACE (lane `live_oracle`; oracle/instrumented.py): a copy of the configured ACE build
rewritten to record the port's trace grain, run in its own worker process beside this process's plain
ACE. Run on both runtimes: `ACE_ASSEMBLY=<mono or .NET 10 build> pytest -m live_oracle tests/oracle`.
benchmarks/instrumented_corpus.py runs the whole corpus through it."""

import pytest

from acconform.compare import compare
from acconform.oracle import default_corpus
from acconform.oracle.recorded import RecordedOracle, scene_kind

pytestmark = pytest.mark.live_oracle

SAMPLE = 14  # corpus scenes, stratified by kind (ticks, indoor, buildings, obstacles, terrain, bsp)


@pytest.fixture(scope="session")
def traced(live):
    from acconform.oracle.instrumented import TracedAce

    t = TracedAce(live.location.assembly, live.location.runtime, say=None)
    yield t
    t.close()


@pytest.fixture(scope="session")
def sample(live):
    corpus = RecordedOracle(default_corpus(live.location.runtime))
    return [corpus._record(e).scene for e in corpus.select(n=SAMPLE, seed=3)]


def test_every_anchor_of_the_port_names_a_method_of_the_ace_build(live):
    from acconform.oracle.instrumented import unresolved

    assert unresolved(live.location) == []


def test_an_instrumented_ace_answers_each_scene_of_a_corpus_sample_exactly_as_the_plain_one(live, traced, sample):
    kinds = set()
    for scene in sample:
        plain = live.run(scene)
        recording, records = traced.trace(scene)
        assert compare(recording, plain, "exact") == [], scene_kind(scene)
        assert compare(traced.run(scene), plain, "exact") == [], scene_kind(scene)
        assert records, "a traced run writes records"
        kinds.add(scene_kind(scene))
    assert {"ticks", "terrain", "obstacles"} <= kinds


def test_aces_trace_of_a_scene_is_the_same_first_in_a_fresh_worker_as_after_other_scenes(live, sample):
    """A trace is a function of the scene alone: ACE's type initializers (ObjCell.EmptyCell's `new ObjCell()`,
    PhysicsGlobals.DummySphere's Sphere) run once a process, wherever its JIT first needs them, and write no record.
    Outside a tick scene the mover's clock is the wall clock (compared as 0)."""
    from dataclasses import replace

    from acconform.oracle.instrumented import TracedAce

    def steady(records):
        return [r if r.mover is None or r.tick is not None else replace(r, mover=replace(r.mover, update_time=0.0))
                for r in records]

    scenes = sample[:4]
    for order in (scenes, scenes[::-1]):
        fresh = TracedAce(live.location.assembly, live.location.runtime, say=None)
        try:
            first = [steady(fresh.trace(scene)[1]) for scene in order]
            again = [steady(fresh.trace(scene)[1]) for scene in order[::-1]][::-1]
        finally:
            fresh.close()
        for scene, a, b in zip(order, first, again):
            assert a == b, f"{scene_kind(scene)}: {len(a)} records first, {len(b)} after the others"


def test_aces_own_trace_and_the_ports_agree_on_the_sample_at_the_grain_both_write(live, traced, sample):
    """Buildings too: a landblock with buildings is built, its buildings placed, before the run on both sides (the
    facade's BuildScene, the port's LScape), and the EnvCells behind a building's portal load in the same order."""
    from acconform.port.run import traced_run
    from acconform.trace import against_ace

    assert "buildings" in {scene_kind(scene) for scene in sample}
    for scene in sample:
        _, ace = traced.trace(scene)
        _, port = traced_run(scene, "exact", live.location.runtime)
        d = against_ace(ace, port, traced.kinds, scene.ticks is not None, traced.overloaded)
        assert d is None, f"{scene_kind(scene)}: {d.routine} {d.field}: ACE {d.a_value!r}, port {d.b_value!r}"


def test_aces_own_trace_and_the_ports_agree_on_building_scenes_whose_run_first_reaches_the_buildings_landblock(
        live, traced):
    """Issue 20's named building scenes whose run (or placement) is the first to reach the landblock with the
    building (tests/port/cell/building_load_order.py): built on first use, the port placed the building there, where
    ACE's trace has the facade's building of the world, and the traces parted for no bug."""
    import sys
    from pathlib import Path

    from acconform.port.run import traced_run
    from acconform.trace import against_ace

    sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "port" / "cell"))
    from building_load_order import SCENES  # noqa: E402
    from building_scenes import load  # noqa: E402

    named, _ = load()
    for name in SCENES:
        scene = named[name]
        _, ace = traced.trace(scene)
        _, port = traced_run(scene, "exact", live.location.runtime)
        d = against_ace(ace, port, traced.kinds, scene.ticks is not None, traced.overloaded)
        assert d is None, f"{name}: {d.routine} {d.field}: ACE {d.a_value!r}, port {d.b_value!r}"


def test_a_planted_sign_flip_is_named_in_cliff_slide_against_aces_trace_as_against_the_ports(live, traced, monkeypatch):
    """The planted bug of tests/runner/mutants.py (cliff_slide_sign_flipped) on the terrain scene its
    campaign shrank to: explain names the same routine and field against ACE's trace as against the port's."""
    import sys
    from pathlib import Path

    from acconform.case import load_document
    from acconform.explain import explain_case

    sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "runner"))
    from mutants import MUTATIONS, load_mutant  # noqa: E402

    case = load_document(str(Path(__file__).with_name("data") / "cliff_slide_sign_flipped.case.json"))
    run = load_mutant([m.name for m in MUTATIONS].index("cliff_slide_sign_flipped"))
    import importlib

    mutant = importlib.import_module(run.__module__)

    class Planted:  # the mutant as an implementation that traces (its own port's tracing)
        name, command, traces = "planted", ["planted"], True

        def run_traced(self, scene):
            outcome, records = mutant.traced_run(scene, "exact", live.location.runtime)
            return outcome, records, None

    runtime = live.location.runtime
    against_port = explain_case(case, Planted(), "exact", runtime)
    against_ace = explain_case(case, Planted(), "exact", runtime, live.run(case.scene), "live ACE", traced_ace=traced)
    assert against_ace.reference_name == "ACE" and against_ace.divergence is not None
    assert against_ace.divergence.key() == against_port.divergence.key() == "Transition.cs:CliffSlide args"


def test_a_static_boxed_by_seven_corners_is_named_in_bbox_local_to_global_while_that_static_is_placed(live, traced, sample,
                                                                                                     monkeypatch):
    """A bug like ACE's #3226, planted in the port: LocalToGlobal carries one corner fewer into the cell's frame.
    The outcome may not change (the box may still reach the same cells); the trace does, while the scene's
    outdoor static is placed, before the run: the comparison with ACE's trace names BBox.LocalToGlobal there."""
    from acconform.numerics import Vector3
    from acconform.port import bbox
    from acconform.port.run import traced_run
    from acconform.trace import against_ace

    def five_corners(self, from_box, from_pos, to_pos):  # the last of the six other corners left out
        fmin, fmax = from_box.min, from_box.max
        self.min = to_pos.local_to_global_from(from_pos, fmin)
        self.max = to_pos.local_to_global_from(from_pos, fmax)
        for corner in ((fmax.x, fmax.y, fmin.z), (fmax.x, fmin.y, fmax.z), (fmin.x, fmax.y, fmax.z), (fmin.x, fmax.y, fmin.z),
                       (fmax.x, fmin.y, fmin.z)):
            self.adjust_bbox(to_pos.local_to_global_from(from_pos, Vector3(*corner)))

    def boxes_a_part(scene):  # a static placed by its parts' boxes (a cylinder's placement reads no box)
        return any(r.anchor == "BBox.cs:LocalToGlobal" and r.placing for r in traced_run(scene)[1])

    scene = next(s for s in sample if s.objects and boxes_a_part(s))
    _, ace = traced.trace(scene)
    monkeypatch.setattr(bbox.BBox, "local_to_global", bbox.BBox.local_to_global)  # restored after the test
    wrapped = bbox.BBox.local_to_global
    from acconform.port import anchors

    key = next(k for k, fn in anchors.FUNCTIONS.items() if fn is wrapped)
    monkeypatch.setitem(anchors.FUNCTIONS, key, five_corners)
    monkeypatch.setattr(bbox.BBox, "local_to_global", five_corners)
    _, port = traced_run(scene, "exact", live.location.runtime)
    d = against_ace(ace, port, traced.kinds, scene.ticks is not None, traced.overloaded)
    assert d is not None and d.routine == "BBox.cs:LocalToGlobal" and d.placing in {o.id for o in scene.objects}
