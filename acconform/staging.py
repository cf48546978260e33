"""Staging: the mover's conventions the oracle and the port share (the scene does not carry them).

A scene does not carry everything ACE would read for the mover, so both sides apply the same
data (documented in docs/oracle.md's audit): the mover's id and its Setup's Height and Radius.
They live here, once, so they cannot drift. Static objects need none: they are written as the
DAT records ACE reads (acconform/dat.py) and placed by ACE's own code on each side.
"""

from __future__ import annotations

from .scene import Scene

MOVER_ID = 0x50000001  # the mover is a player-range PhysicsObj (PhysicsObj.IsPlayer), as ACE's players are


def mover_setup_dims(scene: Scene) -> tuple[float, float]:
    """Setup Height and Radius the oracle gives the mover: top of the highest sphere, largest radius."""
    sph = scene.mover.spheres
    return max(s.center[2] + s.radius for s in sph), max(s.radius for s in sph)
