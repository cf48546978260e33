"""PhysicsTimer: CurrentTime -- the physics clock, ACE's Common/PhysicsTimer.cs.

In ACE `PhysicsTimer.CurrentTime` is `Timers.PortalYearTicks`, a static double the server's
WorldManager advances once per world tick (the oracle sets it through its internal setter). The
port has no statics: a run owns one PhysicsTimer, hands it to every PhysicsObj it makes (through
the run's PortalDat, which carries the other engine statics), and sets `current_time` itself --
to a tick scene's `Ticks.times()`, never to the wall clock. A scene without ticks never moves it:
nothing in a single transition or a placement observes the clock (every CollisionRecord's age is 0).
"""

from __future__ import annotations

from dataclasses import dataclass

from .anchors import harness


@dataclass(slots=True, eq=False)
class PhysicsTimer:
    current_time: float = 0.0  # PhysicsTimer.CurrentTime (Timers.PortalYearTicks): double seconds

    @harness("sets the run's clock (the oracle sets Timers.PortalYearTicks by reflection)")
    def set(self, time: float) -> None:
        self.current_time = float(time)
