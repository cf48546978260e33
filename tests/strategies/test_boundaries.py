"""strategies/boundaries.py: solved geometry lands on its threshold's bits through the port's
make_plane, for the wedge shape the strategies really build."""

import pytest

from acconform.numerics import f32_bits
from acconform.port.constants import FLOOR_Z, LANDING_Z
from acconform.strategies import boundaries as bd
from acconform.strategies import shapes as sh


def test_boundary_table_holds_each_threshold_and_the_ulp_either_side():
    assert bd.Z_BOUNDARIES["floor_z"] == f32_bits(FLOOR_Z) == 0x3F2A0751
    assert bd.Z_BOUNDARIES["landing_z"] == f32_bits(LANDING_Z) == 0x3DB27EB0
    for name in ("floor_z", "landing_z"):
        assert bd.Z_BOUNDARIES[f"{name}-1ulp"] == bd.Z_BOUNDARIES[name] - 1
        assert bd.Z_BOUNDARIES[f"{name}+1ulp"] == bd.Z_BOUNDARIES[name] + 1


@pytest.mark.anchor("CPolygon::make_plane")
@pytest.mark.parametrize("name", sorted(bd.Z_BOUNDARIES))
def test_every_solved_wedge_slope_has_exactly_the_target_normal_z(name):
    target = bd.Z_BOUNDARIES[name]
    wedges = bd.exact_wedges(target)
    assert len(wedges) >= 10, f"too few ramp sizes reach {name}: {len(wedges)}"
    for sx, sy, sz in wedges:
        slope = sh.wedge(sx, sy, sz).polygons[0]
        assert slope.vertices == bd.slope_polygon(sx, sy, sz).vertices
        assert bd.plane_normal_z_bits(slope) == target, (name, sx, sy, sz)


@pytest.mark.anchor("CPolygon::make_plane")
def test_a_rise_one_ulp_off_the_solution_misses_the_floor_z_target():
    # the search finds a real knife edge, not a value that any nearby rise would give
    sx, sy, sz = bd.exact_wedges(bd.Z_BOUNDARIES["floor_z"])[0]
    from acconform.numerics import f32_from_bits
    misses = [bd.plane_normal_z_bits(bd.slope_polygon(sx, sy, f32_from_bits(f32_bits(sz) + k))) != bd.Z_BOUNDARIES["floor_z"]
              for k in (-8, 8)]
    assert all(misses)
