"""The straddle policy draws statics across cell borders, landblock borders and landblock corners often,
of every kind, from both sides, and the BSP shapes the validator used to refuse (strategies/placement.py)."""

from __future__ import annotations

from collections import Counter

import pytest

from acconform.scene import BSPLeaf, BSPNode, BSPShape, CylSphereShape, Frame, Position, SphereRec, SphereShape, StaticObject, validate_scene
from acconform.strategies import sample_scenes
from acconform.strategies.placement import placement_table, scene_tags
from acconform.strategies.shapes import box, leaf_root, zero_radius_empty_leaves


@pytest.fixture(scope="module")
def bsp_scenes():
    return list(sample_scenes(("bsp",), 600, 31))


def test_straddling_statics_are_drawn_often_across_every_kind_of_border(bsp_scenes):
    table = dict(placement_table(bsp_scenes))
    for border in ("cell border", "landblock border", "landblock corner"):
        assert table.get(f"across a {border}", 0) >= 20, (border, table)
    assert table["across a landblock border: mover from the neighbour landblock"] >= 20
    assert table["across a landblock border: mover from the own landblock"] >= 20
    assert table["across a landblock border: turned"] >= 20


def _straddle_labels(scenes, kind):
    return Counter(s.name.split(":")[1] for s in scenes if s.name.startswith(f"{kind}:straddle"))


def test_the_straddle_policy_draws_boxes_and_the_odd_bsp_trees_in_bsp_campaigns(bsp_scenes):
    labels = _straddle_labels(bsp_scenes, "bsp")
    kinds = {label.rsplit("-", 1)[1] for label in labels}
    assert kinds == {"bsp", "leaf_root", "zero_radius_leaves"}, labels
    assert sum(labels.values()) >= len(bsp_scenes) // 10


def test_the_straddle_policy_draws_spheres_and_cylspheres_in_obstacle_campaigns():
    scenes = list(sample_scenes(("obstacles",), 300, 31))
    labels = _straddle_labels(scenes, "obstacles")
    kinds = {label.rsplit("-", 1)[1] for label in labels}
    assert kinds == {"sphere", "cylsphere"}, labels
    assert sum(labels.values()) >= len(scenes) // 10


def test_leaf_root_and_zero_radius_leaf_shapes_are_valid_scenes(bsp_scenes):
    for s in bsp_scenes:
        if {"shape: BSP root is a leaf", "shape: a leaf sphere of radius 0"} & scene_tags(s):
            assert validate_scene(s) == s


def test_scene_tags_name_the_border_the_object_reaches_over():
    def one(shape, x, y):
        from acconform.scene import Mover

        o = StaticObject(0x70000000, Position(0xA9B40001 | (int(x // 24) * 8 + int(y // 24)), Frame((x, y, 0.0))), shape)
        m = Mover((SphereRec((0.0, 0.0, 0.5), 0.5),), o.position, o.position, 0.4, 0.4)
        from acconform.scene import Scene

        return scene_tags(Scene((), m, (o,)))

    ball = SphereShape(SphereRec((0.0, 0.0, 0.5), 1.0))
    assert "across a cell border" in one(ball, 23.5, 10.0)
    assert "across a landblock border" in one(ball, 191.5, 10.0)
    assert "across a landblock corner" in one(ball, 191.5, 191.5)
    assert not any(t.startswith("across") for t in one(ball, 12.0, 12.0))
    assert "across a landblock border: cylsphere" in one(CylSphereShape((0.0, 0.0, 0.0), 1.0, 1.0), 191.5, 10.0)
    assert "shape: BSP root is a leaf" in one(leaf_root(box(1.0, 1.0, 1.0)), 12.0, 12.0)
    assert "shape: a leaf sphere of radius 0" in one(zero_radius_empty_leaves(box(1.0, 1.0, 1.0)), 12.0, 12.0)
