"""check / repro / show / coverage from the command line: exit codes and what they print."""

from __future__ import annotations

import dataclasses
import json
import warnings

import pytest

from acconform.case import Case, Versions, write_document
from acconform.cli import main
from acconform.compare import compare, render
from acconform.strategies import sample_scenes

warnings.simplefilter("ignore", RuntimeWarning)


def _port():
    from acconform.port.run import run_scene

    return run_scene


def _case(tmp_path, tamper: bool) -> str:
    run_scene = _port()
    scene = next(iter(sample_scenes(("terrain",), 1, 11)))
    port = run_scene(scene)
    oracle = dataclasses.replace(port, walkable=not port.walkable) if tamper else port
    case = Case(scene, port, oracle, tuple(render(compare(port, oracle))), "11", "exact", Versions("0.1.0", "", ""))
    return str(write_document(tmp_path / "case.json", case))


def test_check_without_ace_or_corpus_exits_2_with_a_clear_message(no_ace, tmp_path, capsys):
    empty = tmp_path / "corpus"
    empty.mkdir()
    assert main(["check", "--corpus", str(empty), "-n", "5", "--no-progress"]) == 2
    err = capsys.readouterr().err
    assert "no ACE assembly is configured" in err and "holds no" in err


def test_repro_of_a_case_that_still_fails_prints_the_difference_and_exits_1(no_ace, tmp_path, capsys):
    path = _case(tmp_path, tamper=True)
    assert main(["repro", path]) == 1
    out = capsys.readouterr().out
    assert "still fails" in out and "walkable: port=" in out


def test_repro_of_a_case_that_no_longer_fails_says_so_and_exits_0(no_ace, tmp_path, capsys):
    path = _case(tmp_path, tamper=False)
    assert main(["repro", path]) == 0
    assert "no longer fails" in capsys.readouterr().out


def test_repro_and_show_name_the_bad_field_of_a_broken_file_and_exit_2(tmp_path, capsys):
    path = _case(tmp_path, tamper=True)
    doc = json.loads(open(path).read())
    doc["scene"]["mover"]["step_up_height"] = "high"
    bad = tmp_path / "bad.json"
    bad.write_text(json.dumps(doc))
    assert main(["repro", str(bad)]) == 2
    assert "scene.mover.step_up_height" in capsys.readouterr().err
    assert main(["show", str(bad)]) == 2
    assert "scene.mover.step_up_height" in capsys.readouterr().err


def test_show_prints_a_case_readably(tmp_path, capsys):
    path = _case(tmp_path, tamper=True)
    assert main(["show", path]) == 0
    out = capsys.readouterr().out
    for needle in ("1 difference", "landblock 0x", "mover:", "begin 0x", "port: ok=", "oracle: ok="):
        assert needle in out


def test_show_prints_an_indoor_scene_readably(capsys):
    from pathlib import Path

    assert main(["show", str(Path(__file__).parents[2] / "examples" / "two_rooms.json")]) == 0
    out = capsys.readouterr().out
    for needle in ("landblock 0x01D9FFFF: no terrain", "environment 0x0D000001: 3 cell structures",
                   "EnvCell 0x01D90100 at (48, 48, -10) rot (1, 0, 0, 0): structure 1 of 0x0D000001, portals to 0x0101"):
        assert needle in out


def test_show_prints_a_placement_and_what_it_left(tmp_path, capsys):
    from pathlib import Path

    from acconform.case import parse_document
    from acconform.port.run import run_scene

    scene = parse_document(json.loads((Path(__file__).parents[2] / "examples" / "placement_wall_push.json").read_text()))
    path = tmp_path / "outcome.json"
    path.write_text(json.dumps(run_scene(scene).to_json()))
    assert main(["show", str(Path(__file__).parents[2] / "examples" / "placement_wall_push.json")]) == 0
    assert "placed there first by ACE's SetPosition: flags none" in capsys.readouterr().out
    assert main(["show", str(path)]) == 0
    out = capsys.readouterr().out
    assert "outcome of the placement: OK, position 0xA9B40100 (64.5199966, 60, 20), CurCell 0xA9B40100" in out


def test_coverage_prints_a_branch_table_per_1000_scenes(capsys):
    _port()
    assert main(["coverage", "--branches", "-n", "40", "--seed", "1"]) == 0
    out = capsys.readouterr().out
    assert "scenes/1000" in out and "step_down:ok" in out


def test_a_tick_case_and_show_put_the_first_differing_tick_on_top(tmp_path, capsys):
    from pathlib import Path

    from acconform.case import load_document
    from acconform.outcome import Outcome
    from acconform.runner import make_case

    root = Path(__file__).parents[2]
    scene = load_document(root / "examples" / "tick_jump.json")
    ace = Outcome.from_json(json.loads((root / "tests" / "oracle" / "data" / "ace_tick_outcomes.json").read_text())
                            ["outcomes"]["mono"]["tick_jump"])
    ticks = list(ace.ticks)
    ticks[9] = dataclasses.replace(ticks[9], origin=(ticks[9].origin[0], ticks[9].origin[1], 25.0))
    ticks[4] = dataclasses.replace(ticks[4], jumped_this_frame=not ticks[4].jumped_this_frame)
    port = dataclasses.replace(ace, ticks=tuple(ticks), static_cells=((0xA9B40001,),))
    case = make_case(scene, port, ace, compare(port, ace), 7, "exact", Versions("0.1.0", "", ""))
    assert case.differences[0].startswith("ticks[4].jumped_this_frame: port=")
    path = write_document(tmp_path / "tick_case.json", case)
    assert main(["show", str(path)]) == 0
    lines = capsys.readouterr().out.splitlines()
    assert lines[1].startswith("first differing tick: 4 of 40: ticks[4].jumped_this_frame: port=")
    assert "  ticks: 40 by update_object, clock from 1000.0 to 1001.5999999999985" in lines
    assert any(line.startswith("  tick 9: updated at") and "25)" in line for line in lines)


def test_a_scene_writers_bad_count_is_one_line_and_exit_2(capsys):
    import sys
    from pathlib import Path

    sys.path.insert(0, str(Path(__file__).resolve().parent))
    from scene_writer import scene_arguments

    with pytest.raises(SystemExit) as e:
        scene_arguments("writes scenes", 10, 1).parse_args(["/tmp/out", "-n", "ten"])
    err = capsys.readouterr().err
    assert e.value.code == 2 and err.count("\n") == 1 and "argument -n: invalid int value: 'ten'" in err
