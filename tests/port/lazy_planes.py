"""Reading a port Polygon's plane without making it: whether make_plane_when_read left it unset, and
its bits once made (the lazy-plane tests of terrain and of DAT polygons share them)."""

from __future__ import annotations


def plane_unset(polygon) -> bool:
    """The plane has not been made yet (reading `polygon.plane` would make it)."""
    try:
        object.__getattribute__(polygon, "plane")
    except AttributeError:
        return True
    return False


def plane_bits(polygon) -> tuple:
    n, d = polygon.plane.normal, polygon.plane.d
    return tuple(float(v).hex() for v in (n.x, n.y, n.z, d))  # exact in either mode
