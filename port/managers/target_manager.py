"""TargetManager: TargetManager(physObj), SetTarget, SetTargetQuantum, HandleTargetting, CheckAndUpdateVoyeur, GetInterpolatedPosition, ClearTarget, NotifyVoyeurOfEvent, ReceiveUpdate, AddVoyeur, SendVoyeurUpdate, RemoveVoyeur.

ACE's Managers/TargetManager.cs (namespace Combat): the two halves of targeting. As a *voyeur*, an
object sets a target (SetTarget registers it with the target's TargetManager through
GetObjectA(...).add_voyeur) and receives updates (ReceiveUpdate -> PhysicsObj.HandleUpdateTarget,
which the MoveToManager and StickyManager read). As a *target*, an object keeps its VoyeurTable
(a .NET Dictionary, enumerated in its entry order) and, every half second (HandleTargetting), sends
each voyeur its position projected `quantum` seconds ahead once it has moved more than the voyeur's
radius from the last one sent. The clock is the object's run's PhysicsTimer (a double).
"""

from __future__ import annotations

from dataclasses import dataclass

from acconform.numerics import cast_float

from ..anchors import anchor
from ..combat.target_info import TargetInfo, TargetStatus
from ..combat.targetted_voyeur_info import TargettedVoyeurInfo
from ..transition.cell_array import NetDictionary
from ..vec import normalize_check_small

UPDATE_INTERVAL = 0.5  # HandleTargetting: `CurrentTime - LastUpdateTime < 0.5f` (exact)
TARGET_TIMEOUT = 10.0  # HandleTargetting: an Undefined target `LastUpdateTime + 10.0f` ago times out (exact)


@dataclass(slots=True, eq=False)
class TargetManager:
    physics_obj: object = None
    target_info: TargetInfo | None = None
    voyeur_table: NetDictionary | None = None  # object id -> TargettedVoyeurInfo
    last_update_time: float = 0.0  # double

    @staticmethod
    @anchor("TargetManager::TargetManager", "TargetManager.cs:TargetManager(PhysicsObj)")
    def create(phys_obj) -> "TargetManager":
        return TargetManager(physics_obj=phys_obj)

    @anchor("TargetManager::SetTarget", "TargetManager.cs:SetTarget")
    def set_target(self, context_id: int, object_id: int, radius, quantum: float) -> None:
        if self.physics_obj is None:
            return

        self.clear_target()

        if object_id == 0:
            failed_target_info = TargetInfo()
            failed_target_info.context_id = context_id
            failed_target_info.status = TargetStatus.TimedOut
            self.physics_obj.handle_update_target(failed_target_info)
            return

        self.target_info = TargetInfo.create(context_id, object_id, radius, quantum, self.physics_obj.timer)
        target = self.physics_obj.get_object_a(object_id)
        if target is not None:
            target.add_voyeur(self.physics_obj.id, radius, quantum)

    @anchor("TargetManager::SetTargetQuantum", "TargetManager.cs:SetTargetQuantum")
    def set_target_quantum(self, quantum: float) -> None:
        if self.physics_obj is None or self.target_info is None:
            return

        self.target_info.quantum = float(quantum)

        target_obj = self.physics_obj.get_object_a(self.target_info.object_id)
        if target_obj is None:
            return

        target_obj.add_voyeur(self.physics_obj.id, self.target_info.radius, quantum)

    @anchor("TargetManager::HandleTargetting", "TargetManager.cs:HandleTargetting")
    def handle_targetting(self) -> None:
        if self.physics_obj is None:
            return

        now = self.physics_obj.timer.current_time  # PhysicsTimer.CurrentTime
        if now - self.last_update_time < UPDATE_INTERVAL:
            return

        if self.target_info is not None and self.target_info.target_position is None:
            return

        if (self.target_info is not None and self.target_info.status == TargetStatus.Undefined
                and self.target_info.last_update_time + TARGET_TIMEOUT < now):
            self.target_info.status = TargetStatus.TimedOut
            self.physics_obj.handle_update_target(self.target_info.copy())

        if self.voyeur_table is not None:
            for voyeur in self.voyeur_table.values():  # .Values.ToList(): a snapshot
                self.check_and_update_voyeur(voyeur)

        self.last_update_time = self.physics_obj.timer.current_time

    @anchor("TargetManager::CheckAndUpdateVoyeur", "TargetManager.cs:CheckAndUpdateVoyeur")
    def check_and_update_voyeur(self, voyeur: TargettedVoyeurInfo) -> None:
        new_pos = self.get_interpolated_position(voyeur.quantum)
        if new_pos is not None:
            if new_pos.distance(voyeur.last_sent_position) > voyeur.radius:
                self.send_voyeur_update(voyeur, new_pos, TargetStatus.OK)

    @anchor("TargetManager::GetInterpolatedPosition", "TargetManager.cs:GetInterpolatedPosition")
    def get_interpolated_position(self, quantum: float):
        if self.physics_obj is None:
            return None

        pos = self.physics_obj.position.copy()
        velocity = self.physics_obj.get_velocity()
        pos.frame.origin = pos.frame.origin + velocity * cast_float(velocity.x, quantum)
        return pos

    @anchor("TargetManager::ClearTarget", "TargetManager.cs:ClearTarget")
    def clear_target(self) -> None:
        if self.target_info is None:
            return

        target_obj = self.physics_obj.get_object_a(self.target_info.object_id)
        if target_obj is not None:
            target_obj.remove_voyeur(self.physics_obj.id)

        if self.target_info is not None:
            self.target_info = None

    @anchor("TargetManager::NotifyVoyeurOfEvent", "TargetManager.cs:NotifyVoyeurOfEvent")
    def notify_voyeur_of_event(self, status: TargetStatus) -> None:
        if self.physics_obj is None or self.voyeur_table is None:
            return

        for voyeur in self.voyeur_table.values():
            self.send_voyeur_update(voyeur, self.physics_obj.position, status)

    @anchor("TargetManager::ReceiveUpdate", "TargetManager.cs:ReceiveUpdate")
    def receive_update(self, update: TargetInfo) -> None:
        if self.physics_obj is None or self.target_info is None or self.target_info.object_id != update.object_id:
            return

        self.target_info = update.copy()
        self.target_info.last_update_time = self.physics_obj.timer.current_time
        self.target_info.interpolated_heading = self.physics_obj.position.get_offset(self.target_info.interpolated_position)

        small, self.target_info.interpolated_heading = normalize_check_small(self.target_info.interpolated_heading)
        if small:
            h = self.target_info.interpolated_heading
            zero, one = type(h.x)(0.0), type(h.x)(1.0)
            self.target_info.interpolated_heading = type(h)(zero, zero, one)  # Vector3.UnitZ

        self.physics_obj.handle_update_target(self.target_info.copy())

        if update.status == TargetStatus.ExitWorld:
            self.clear_target()

    @anchor("TargetManager::AddVoyeur", "TargetManager.cs:AddVoyeur")
    def add_voyeur(self, object_id: int, radius, quantum: float) -> None:
        if self.voyeur_table is not None:
            existing_info = self.voyeur_table[object_id] if object_id in self.voyeur_table else None
            if existing_info is not None:
                existing_info.radius = radius
                existing_info.quantum = float(quantum)
                return
        else:
            self.voyeur_table = NetDictionary()

        info = TargettedVoyeurInfo.create(object_id, radius, quantum)
        self.voyeur_table.add(object_id, info)

        self.send_voyeur_update(info, self.physics_obj.position, TargetStatus.OK)

    @anchor("TargetManager::SendVoyeurUpdate", "TargetManager.cs:SendVoyeurUpdate")
    def send_voyeur_update(self, voyeur: TargettedVoyeurInfo, pos, status: TargetStatus) -> None:
        voyeur.last_sent_position = pos.copy()

        info = TargetInfo.create(0, self.physics_obj.id, voyeur.radius, voyeur.quantum, self.physics_obj.timer)
        info.target_position = self.physics_obj.position  # the object's own Position (no copy in ACE)
        info.interpolated_position = pos.copy()
        info.velocity = self.physics_obj.get_velocity()
        info.status = status

        voyeur_obj = self.physics_obj.get_object_a(voyeur.object_id)
        if voyeur_obj is not None:
            voyeur_obj.receive_target_update(info)

    @anchor("TargetManager::RemoveVoyeur", "TargetManager.cs:RemoveVoyeur")
    def remove_voyeur(self, object_id: int) -> bool:
        if self.voyeur_table is None:
            return False

        return self.voyeur_table.remove(object_id)


__all__ = ["TargetManager"]
