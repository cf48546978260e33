"""Which ACE the oracle found, said in one line, and whether it is the ACE the port follows.

The port follows ACE's physics as of commit 7b47913 (members.ACE_COMMIT). Any other ACE build
loads too, as long as it has the members the oracle uses (members.py): a difference against it
may then be ACE's own change between the two commits, not the port's bug, and `check` says so.

What is known of a build: ACE's build stamp, `ServerBuildInfo.Commit` and its build date (ACE's
CI writes them into ServerBuildInfo_Dynamic.cs; ACE has it since c725acc, 2020-03-24), and the
shape of members ACE changed over the years (SHAPES). `identify` is pure (the runtime reads the
facts), so it is tested without .NET.
"""

from __future__ import annotations

from dataclasses import dataclass

from .members import ACE_BUILD_COMMITS, ACE_COMMIT

STAMP_SINCE = "c725acc, 2020-03-24"  # the commit that gave ACE its build stamp

ABSENT = "absent"  # runtime.shape_of's answer for a member the type lacks


@dataclass(frozen=True, slots=True)
class Shape:
    """A member ACE changed: as 7b47913 has it (`expected`, a type name or ABSENT) since `change`."""

    change: str  # "ACE #2727 (cc0ecff, 2020-10-24)"
    type_name: str
    member: str
    expected: str
    said: str  # what a build with another shape is, "{found}" the shape found


WALL_CLOCK = "ACE #4110 (2e9b8f3, 2024-03-24)"  # PhysicsTimer reads Timers.PortalYearTicks since

# Read by runtime.shape_of when ACE loads; a build shaped otherwise is "7b47913-compatible: no".
SHAPES: tuple[Shape, ...] = (
    Shape("ACE #2727 (cc0ecff, 2020-10-24)", "ACE.Server.Physics.Util.AdjustCell", "AdjustCells",
          "ConcurrentDictionary`2", "AdjustCell.AdjustCells is a {found}"),
    # before it, PhysicsTimer.CurrentTime read a Stopwatch of its own: the facade cannot set the physics
    # clock, so a tick scene's update times are wall time (LiveOracle.unsupported skips tick scenes)
    Shape(WALL_CLOCK, "ACE.Server.Physics.Common.PhysicsTimer", "_timer", ABSENT,
          "PhysicsTimer.CurrentTime reads a {found} (wall time), not Timers.PortalYearTicks"),
)


@dataclass(frozen=True, slots=True)
class AceIdentity:
    follows_port: bool | None  # True: ACE 7b47913; False: another ACE; None: cannot tell (no stamp, shapes agree)
    line: str  # "ACE: mono build, ACE.Server 0.0.0.0 sha256:..., commit ..., 7b47913-compatible: yes"
    found: str  # the part of `line` naming the ACE found ("no build stamp; ... as before ACE #2727 ...")
    wall_clock: bool = False  # its physics clock is wall time: tick scenes cannot be run on it

    @property
    def note(self) -> str | None:
        """What `check` says beside its differences when the ACE found is not the port's (None: it is)."""
        if self.follows_port is not False:
            return None
        return (f"note: the ACE found is not ACE {ACE_COMMIT}, the commit the port follows ({self.found}): a difference "
                f"here may be ACE's own change between the two, not the port's bug (`acconform repro CASE` with an ACE "
                f"{ACE_COMMIT} build tells)")


def identify(runtime: str, ace_version: str, stamp: str | None, stamp_date: str | None,
             shapes: dict[str, str | None]) -> AceIdentity:
    """`runtime` "mono"/"coreclr"; `ace_version` "ACE.Server 0.0.0.0 sha256:..."; `stamp` the build's
    ServerBuildInfo.Commit (None: the build has none) and `stamp_date` its build date ("2026-08-08");
    `shapes` each SHAPES entry's shape as found, by its change (a type name, ABSENT, or None: not read)."""
    other = [sh for sh in SHAPES if shapes.get(sh.change) not in (None, sh.expected)]
    changed = [f"{sh.said.format(found=shapes[sh.change])} (as before {sh.change})" for sh in other]
    if stamp is not None:
        when = f", built {stamp_date}" if stamp_date else ""
        ours = any(stamp.startswith(c) for c in ACE_BUILD_COMMITS)
        found = f"commit {stamp[:12] or '(empty)'} (its ServerBuildInfo stamp{when})"
        if ours and not changed:
            follows: bool | None = True
        else:
            follows = False
    else:
        found = f"no build stamp (ACE before {STAMP_SINCE}, or a build without ServerBuildInfo)"
        follows = False if changed else None
    if changed:
        found += "; " + "; ".join(changed)
    verdict = {True: "yes", False: "no", None: "unknown (no stamp; its members are shaped as 7b47913's)"}[follows]
    build = "mono build" if runtime == "mono" else ".NET build (CoreCLR)"
    return AceIdentity(follows, f"ACE: {build}, {ace_version}, {found}, {ACE_COMMIT}-compatible: {verdict}", found,
                       wall_clock=any(sh.change == WALL_CLOCK for sh in other))
