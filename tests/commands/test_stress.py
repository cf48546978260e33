"""acconform stress: every derived scene is valid, nudges are exact ULP steps, and the report says
what it compared (port-only with a visible note when no ACE is configured)."""

from __future__ import annotations

import dataclasses

import numpy as np
import pytest

from acconform.cli import main
from acconform.commands.stress import PERTURBATIONS, derive, step, stress
from acconform.numerics import f32_bits
from acconform.port.constants import FLOOR_Z
from acconform.scene import validate_scene
from acconform.strategies import sample_scenes


@pytest.fixture(scope="module")
def bases():
    return [s for k in ("terrain", "bsp", "obstacles") for s in sample_scenes((k,), 4, 3)]


def test_every_perturbation_kind_derives_only_valid_scenes(bases):
    derived = 0
    for kind in PERTURBATIONS:
        for base in bases:
            for v, twin in derive(kind, base, 2):
                for s in (v, twin):
                    if s is not None:
                        validate_scene(s)
                        derived += 1
    assert derived > 100  # the derivations really produced scenes


def test_every_perturbation_kind_applies_to_some_base_scene(bases):
    assert [k for k in PERTURBATIONS if not any(derive(k, b, 1) for b in bases)] == []


def test_a_one_ulp_nudge_moves_each_coordinate_by_exactly_one_float32_step(bases):
    base = bases[0]
    (v, twin), *_ = derive("nudge_end", base, 1)
    assert twin is base
    for a, b in zip(base.mover.end.frame.origin, v.mover.end.frame.origin):
        assert f32_bits(b) - f32_bits(a) == (1 if a > 0 else -1 if a < 0 else f32_bits(b))
    assert step(0.0, 1) == float(np.nextafter(np.float32(0), np.float32(1)))


def test_floor_z_variants_straddle_floor_z_by_one_ulp(bases):
    (below, above), _ = derive("floor_z", bases[0], 1)
    zs = (below.mover.contact_plane.plane.normal[2], above.mover.contact_plane.plane.normal[2])
    assert [f32_bits(z) - f32_bits(FLOOR_Z) for z in zs] == [-1, 1]


def test_a_move_ending_on_a_cell_border_ends_exactly_on_a_24_m_line(bases):
    for base in bases:
        for v, _ in derive("cell_border", base, 1):
            x, y, _z = v.mover.end.frame.origin
            assert x % 24.0 == 0.0 or y % 24.0 == 0.0


def test_world_edge_variants_use_landblock_columns_0x00_and_0xFE(bases):
    xs = {lb.id >> 24 for v, _ in derive("world_edge", bases[0], 1) for lb in v.landblocks}
    ys = {(lb.id >> 16) & 0xFF for v, _ in derive("world_edge", bases[0], 1) for lb in v.landblocks}
    assert 0x00 in xs and 0xFE in xs and 0x00 in ys and 0xFE in ys


def test_a_port_oracle_difference_on_a_stressed_scene_is_counted_and_written_as_a_case(bases, tmp_path):
    from acconform.port.run import run_scene

    def exact(s):
        return run_scene(s)

    def lying_oracle(s):  # ACE stand-in that disagrees on the walkable bit
        o = run_scene(s)
        return dataclasses.replace(o, walkable=not o.walkable)

    stats = stress(bases[:1], ("tiny_sphere",), exact, lambda s: run_scene(s, mode="fast"), lying_oracle,
                   failures_dir=tmp_path)
    assert stats["tiny_sphere"].diff_exact == 2  # the variant and its 1-ULP twin
    assert len(list(tmp_path.glob("case-*.json"))) == 2


def test_stress_without_ace_says_the_oracle_half_is_skipped_and_exits_0(no_ace, tmp_path, capsys):
    code = main(["stress", "-n", "1", "--kinds", "terrain", "--only", "nudge_end,floor_z", "--failures",
                 str(tmp_path)])
    out = capsys.readouterr().out
    assert code == 0
    assert "oracle half skipped" in out
    assert "nudge_end" in out and "floor_z" in out and "1-ULP flips" in out


def test_stress_rejects_an_unknown_perturbation_kind_with_exit_2(no_ace, capsys):
    assert main(["stress", "-n", "1", "--only", "wobble"]) == 2
    assert "unknown perturbation kind 'wobble'" in capsys.readouterr().err
