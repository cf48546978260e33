"""Creature: OnCollideObject; the members of ACE's Creature the physics reads (IsMonster, Faction1Bits, FoeType, the Run skill).

ACE's WorldObjects/Creature.cs (Monster.cs: IsMonster; Creature_Properties.cs: Faction1Bits). A
Creature that is not a monster is an NPC. Real ACE's SetMonsterState computes IsMonster as
``Attackable || TargetingTactic != None`` when it builds a creature; here it is the scene's choice, as
the oracle's stand-in Creature holds it. Faction1Bits and FoeType stay null (no faction, no foe).
"""

from __future__ import annotations

from dataclasses import dataclass

from ..anchors import anchor
from .world_object import WorldObject


@dataclass(slots=True, eq=False, kw_only=True)
class Creature(WorldObject):
    is_monster: bool = False  # IsMonster
    faction1_bits: int | None = None  # Faction1Bits (FactionBits?)
    foe_type: int | None = None  # FoeType (CreatureType?)
    # the skills, vitals and attributes the physics reads (acconform.scene.MoverSkills, scene/8); the defaults are the
    # database-free creature's: no skill, Stamina and Strength 1 (their floors)
    run_skill: int = 0  # GetCreatureSkill(Skill.Run).Current (a uint)
    jump_skill: int = 0  # GetCreatureSkill(Skill.Jump).Current (a uint)
    stamina: int = 1  # Stamina.Current (a uint)
    strength: int = 1  # Strength.Current (a uint)

    @anchor(None, "ACE.Server/WorldObjects/Creature.cs:OnCollideObject")
    def on_collide_object(self, target: WorldObject) -> None:
        if target.report_collisions is False:  # `== false` on a bool?: null goes on
            return

        # `target is Door door` -> door.OnCollideObject(this) and `target is Hotspot hotspot` ->
        # hotspot.OnCollideObject(this): a scene makes no Door or Hotspot WorldObject (a scene's door is a
        # static with no WorldObject), so neither branch is reachable


__all__ = ["Creature"]
