"""ChildList: ChildList(), FindChildIndex, AddChild, RemoveChild -- the objects parented to a PhysicsObj.

ACE's Physics/Common/ChildList.cs: four parallel lists (the child, its frame in the parent's part or
Position, the part index, the holding location id) and a count. PhysicsObj.add_child fills it;
set_parent reaches it through add_child, unset_parent through RemoveChild.

RemoveChild does not decrement NumObjects (ACE): after a removal the count is one past the lists, so
FindChildIndex and remove_shadows_from_cells, which loop to NumObjects, index past the end and throw
ArgumentOutOfRangeException once they get there; the loops over ``Objects`` (enter_cell, leave_cell,
add_shadows_to_cell, recalc_cross_cells) and UpdateChildrenInternal (``Objects.Count``) do not.
"""

from __future__ import annotations

from dataclasses import dataclass, field

from .anchors import anchor, harness
from .errors import ArgumentOutOfRangeException


@dataclass(slots=True, eq=False)
class ChildList:
    num_objects: int = 0
    objects: list = field(default_factory=list)  # PhysicsObj
    frames: list = field(default_factory=list)  # AFrame: the child's frame in its part (or the parent's Position)
    part_numbers: list = field(default_factory=list)  # int
    location_ids: list = field(default_factory=list)  # int: the holding location (0 for a part-and-frame child)

    @anchor("CHILDLIST::FindChildIndex", "ChildList.cs:FindChildIndex")
    def find_child_index(self, obj) -> int:
        for i in range(self.num_objects):
            child = self.item(i)
            if child.equals(obj):
                return i
        return -1

    @anchor("CHILDLIST::add_child", "ChildList.cs:AddChild")
    def add_child(self, obj, frame, part_idx: int, location_id: int) -> None:
        self.objects.append(obj)
        self.frames.append(frame)
        self.part_numbers.append(part_idx)
        self.location_ids.append(location_id)
        self.num_objects += 1

    @anchor("CHILDLIST::remove_child", "ChildList.cs:RemoveChild")
    def remove_child(self, obj) -> bool:
        idx = self.find_child_index(obj)
        if idx == -1:
            return False
        del self.objects[idx]
        del self.frames[idx]
        del self.part_numbers[idx]
        del self.location_ids[idx]
        return True  # NumObjects stays (ACE)

    @harness("Objects[i] as .NET's List<T> indexer: an index past Count throws ArgumentOutOfRangeException")
    def item(self, i: int):
        if not 0 <= i < len(self.objects):
            raise ArgumentOutOfRangeException(f"Objects[{i}] of a ChildList of {len(self.objects)} (NumObjects {self.num_objects})")
        return self.objects[i]
