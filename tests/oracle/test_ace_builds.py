"""The oracle on ACE builds other than the reduced physics builds (issue 44), each in a child process
as a user runs `acconform check`, so one test process can try builds on both runtimes.

- `ACE_FULL_ASSEMBLY`: ACE 7b47913 built by ACE's own `ACE.Server.csproj` (docs/oracle.md, "ACE's
  own ACE.Server.csproj"): it says it is 7b47913, a campaign has no difference, and its real Player
  (made without a character's database record) takes a fall fast enough to hurt as the port does.
- `ACE_2019_ASSEMBLY`: a mono build of ACE of 2019 (docs/oracle.md, "ACE of 2019"): it loads, says
  it is another ACE, skips the tick scenes its wall-time clock cannot run, and says beside any
  difference that it may be ACE's own change.

Each is skipped, naming the variable, when it is not set.
"""

from __future__ import annotations

import json
import os
import subprocess
import sys

import pytest

pytestmark = pytest.mark.live_oracle


def _build(variable: str) -> str:
    path = os.environ.get(variable)
    if not path:
        pytest.skip(f"no {variable}: set it to that ACE build's ACE.Server.dll to run this test (docs/oracle.md)")
    return path


def _check(ace: str, tmp_path, *args) -> tuple[subprocess.CompletedProcess, dict]:
    summary = tmp_path / "summary.json"
    env = dict(os.environ, ACE_ASSEMBLY=ace)
    env.pop("ACE_RUNTIME", None)
    p = subprocess.run([sys.executable, "-m", "acconform.cli", "check", "--no-database", "--keep-going",
                        "--failures", str(tmp_path / "f"), "--json", str(summary), *map(str, args)],
                       env=env, capture_output=True, text=True, timeout=1800, cwd=tmp_path)
    assert summary.exists(), p.stderr[-2000:]
    return p, json.loads(summary.read_text())


def test_ace_built_by_its_own_csproj_says_it_is_7b47913_and_agrees_with_the_port(tmp_path):
    p, s = _check(_build("ACE_FULL_ASSEMBLY"), tmp_path, "-n", 60, "-j", 1)
    assert "7b47913-compatible: yes" in p.stderr and ".NET build (CoreCLR)" in p.stderr
    assert s["oracle"] == "live" and s["cases"]["compared"] == 60 and s["differences"]["total"] == 0, p.stdout
    assert s["ace_note"] is None


# A tick scene whose mover (ReportCollisions) falls onto flat terrain at about 30 m/s: its environment collision
# runs the real Player's HandleFallingDamage with a fall fast enough to hurt (Player_Move.cs: below about -15.75 m/s).
HURTING_FALL = """
import json, sys
from acconform.case import load_document
from acconform.compare import compare
from acconform.impl import make_backend
from acconform.oracle.live import LiveOracle
from acconform.runner import guarded
doc = json.load(open(sys.argv[1]))
doc["mover"]["state"] = ["Gravity", "EdgeSlide", "ReportCollisions"]
doc["ticks"]["steps"][0]["velocity"] = [0.0, 0.0, -30.0]
json.dump(doc, open("fall.json", "w"))
scene = load_document("fall.json")
ace = LiveOracle(say=None).run(scene)
port = guarded(make_backend(None), scene)
print(json.dumps({"errors": [t.error for t in ace.ticks], "first_vz": float(ace.ticks[0].velocity[2]),
                  "landed": any(t.transient_state & 1 for t in ace.ticks), "differences": len(compare(port, ace))}))
"""


def test_a_fall_fast_enough_to_hurt_the_player_on_ace_built_by_its_own_csproj_agrees_with_the_port(tmp_path):
    env = dict(os.environ, ACE_ASSEMBLY=_build("ACE_FULL_ASSEMBLY"))
    env.pop("ACE_RUNTIME", None)
    example = os.path.join(os.path.dirname(__file__), "..", "..", "examples", "tick_fall.json")
    p = subprocess.run([sys.executable, "-c", HURTING_FALL, os.path.abspath(example)], env=env, capture_output=True,
                       text=True, timeout=600, cwd=tmp_path)
    assert p.returncode == 0, p.stderr[-2000:]
    r = json.loads(p.stdout.splitlines()[-1])
    assert r["errors"] == [None] * len(r["errors"]) and r["differences"] == 0
    assert r["first_vz"] < -15.76 and r["landed"]  # it lands, faster than a fall Player.HandleFallingDamage spares


def test_ace_of_2019_loads_as_another_ace_and_skips_the_tick_scenes_it_cannot_run(tmp_path):
    p, s = _check(_build("ACE_2019_ASSEMBLY"), tmp_path, "-n", 12, "-j", 1, "--kinds", "ticks,terrain",
                  "--shrink-budget", 0)
    line = next(x for x in p.stderr.splitlines() if ": ACE: " in x)
    assert "no build stamp" in line and "7b47913-compatible: no" in line and "PhysicsTimer" in line
    assert s["oracle"] == "live" and s["cases"]["skipped_total"] > 0, p.stdout
    assert all(why.startswith("this ACE runs tick scenes on wall time") for why in s["cases"]["skipped"])
    assert "the ACE found is not ACE 7b47913" in s["ace_note"]
    if s["differences"]["total"]:  # ACE's own changes since 2019 are said to be possibly ACE's
        assert "the ACE found is not ACE 7b47913" in p.stdout
