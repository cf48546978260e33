"""Staging: the one convention the oracle and the port share that a scene does not carry: the mover's id.

Everything else ACE would read from DAT files is written as DAT records (acconform/dat.py: the
statics' and the mover's) and made and placed by ACE's own code on each side (docs/oracle.md's
audit). The mover's id lives here, once, so it cannot drift.
"""

MOVER_ID = 0x50000001  # the mover is a player-range PhysicsObj (PhysicsObj.IsPlayer), as ACE's players are

