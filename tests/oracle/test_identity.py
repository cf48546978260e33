"""Which ACE the oracle found, in one line, and whether it is the ACE the port follows (oracle/identity.py).

Any ACE build with the members the oracle uses loads; one that is not ACE 7b47913 is said to be
another ACE, and `check` then says a difference may be ACE's own change, not the port's bug.
"""

from acconform.commands.check import console_summary
from acconform.oracle.identity import SHAPES, WALL_CLOCK, identify
from acconform.outcome import Outcome
from acconform.port.run import run_scene
from acconform.runner import run_campaign

OURS = "bab7a5ca8552cb18f63e08b57234bd9137cd0249"  # 7b47913's own stamp
AS_7B47913 = {sh.change: sh.expected for sh in SHAPES}
AS_2019 = dict(AS_7B47913, **{SHAPES[0].change: "Dictionary`2", WALL_CLOCK: "Stopwatch"})


def test_a_build_stamped_with_ace_7b47913_is_the_ace_the_port_follows():
    who = identify("coreclr", "ACE.Server 1.1.0.0 sha256:0123456789ab", OURS, "2026-08-08", AS_7B47913)
    assert who.follows_port is True and who.note is None and not who.wall_clock
    assert who.line == ("ACE: .NET build (CoreCLR), ACE.Server 1.1.0.0 sha256:0123456789ab, commit bab7a5ca8552 "
                        "(its ServerBuildInfo stamp, built 2026-08-08), 7b47913-compatible: yes")
    stamped_at_build = identify("mono", "ACE.Server 0.0.0.0 sha256:x", "7b47913ae000", None, AS_7B47913)
    assert stamped_at_build.follows_port is True and "built" not in stamped_at_build.line


def test_a_build_stamped_with_another_commit_loads_as_another_ace_and_its_differences_are_said_to_be_aces():
    who = identify("coreclr", "ACE.Server 1.1.0.0 sha256:x", "0123456789abcdef0123", "2025-01-02", AS_7B47913)
    assert who.follows_port is False and who.line.endswith("7b47913-compatible: no")
    assert "commit 0123456789ab" in who.line and "built 2025-01-02" in who.line
    assert "not ACE 7b47913" in who.note and "ACE's own change" in who.note and "not the port's bug" in who.note


def test_a_2019_build_without_a_stamp_is_told_by_the_shape_of_its_members():
    who = identify("mono", "ACE.Server 0.0.0.0 sha256:x", None, None, AS_2019)
    assert who.follows_port is False and who.line.startswith("ACE: mono build, ")
    assert "no build stamp" in who.line and "AdjustCell.AdjustCells is a Dictionary`2 (as before ACE #2727" in who.line
    assert "PhysicsTimer.CurrentTime reads a Stopwatch (wall time)" in who.line and who.line.endswith("7b47913-compatible: no")
    assert who.wall_clock  # its tick scenes cannot be run (LiveOracle.unsupported)


def test_a_physics_clock_of_wall_time_alone_makes_another_ace_with_tick_scenes_it_cannot_run():
    who = identify("coreclr", "ACE.Server 1.1.0.0 sha256:x", None, None, dict(AS_7B47913, **{WALL_CLOCK: "Stopwatch"}))
    assert who.wall_clock and who.follows_port is False and "AdjustCells" not in who.line


def test_a_build_without_a_stamp_shaped_as_7b47913_cannot_be_told_and_gets_no_note():
    who = identify("mono", "ACE.Server 0.0.0.0 sha256:x", None, None, AS_7B47913)
    assert who.follows_port is None and who.note is None and "7b47913-compatible: unknown" in who.line


class OtherAce:
    """A live oracle on another ACE, as check sees it: its answers, and its note (oracle/live.py)."""

    def __init__(self, note):
        self.ace_note = note

    def run(self, scene):
        return Outcome(error="Planted: another ACE's answer")


def test_check_says_beside_its_differences_that_another_ace_may_have_made_them():
    note = identify("mono", "ACE.Server 0.0.0.0 sha256:x", None, None, AS_2019).note
    differs = run_campaign(lambda s: run_scene(s), OtherAce(note).run, kinds=("terrain",), n=2, seed=1,
                           failures_dir=None, database=None, shrink_budget=2)
    assert differs.found and note in console_summary(differs, [], keep_going=False)
    agrees = run_campaign(lambda s: run_scene(s), lambda s: run_scene(s), kinds=("terrain",), n=2, seed=1,
                          failures_dir=None, database=None)
    agrees.ace_note = note
    assert note not in console_summary(agrees, [], keep_going=False)  # nothing to explain without a difference


class WallClockAce(OtherAce):
    """A live ACE whose physics clock is wall time: it cannot run tick scenes (LiveOracle.unsupported)."""

    def __init__(self):
        super().__init__(None)
        self.ran = []

    def unsupported(self, scene):
        return "this ACE runs tick scenes on wall time (PhysicsTimer before ACE #4110)" if scene.ticks is not None else None

    def run(self, scene):
        self.ran.append(scene)
        return run_scene(scene)


def test_a_campaign_skips_the_scenes_its_ace_cannot_run_and_says_why():
    ace = WallClockAce()
    r = run_campaign(lambda s: run_scene(s), ace.run, kinds=("terrain", "ticks"), n=12, seed=2, failures_dir=None,
                     database=None)
    assert not r.found and r.skipped and all(s.ticks is None for s in ace.ran)
    line = next(x for x in console_summary(r, [], keep_going=False) if x.startswith("skipped "))
    assert "scenes this ACE cannot run: this ACE runs tick scenes on wall time" in line
