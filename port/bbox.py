"""BBox: AdjustBBox, GetCorners, LocalToGlobal, LocalToLocal -- the axis-aligned box a GfxObj's vertices span (ACE's Physics/Collision/BBox.cs).

GfxObj.Init builds a part's box from its vertices; LandCell.add_all_outside_cells (the parts
overload) carries it into the placing cell's landblock with LocalToGlobal, which starts from the
box's two corners as transformed (so a rotation can leave Min above Max on an axis) and then
widens it by the six other corners.
"""

from __future__ import annotations

from dataclasses import dataclass

from acconform.numerics import Vector3

from .anchors import anchor


@dataclass(slots=True, eq=False)
class BBox:
    min: Vector3 | None = None
    max: Vector3 | None = None

    @anchor(None, "BBox.cs:AdjustBBox")
    def adjust_bbox(self, v: Vector3) -> None:
        mn, mx = self.min, self.max
        if v.x < mn.x:
            mn = mn.with_x(v.x)
        if v.y < mn.y:
            mn = mn.with_y(v.y)
        if v.z < mn.z:
            mn = mn.with_z(v.z)
        if v.x > mx.x:
            mx = mx.with_x(v.x)
        if v.y > mx.y:
            mx = mx.with_y(v.y)
        if v.z > mx.z:
            mx = mx.with_z(v.z)
        self.min, self.max = mn, mx

    @anchor(None, "BBox.cs:GetCorners")
    def get_corners(self) -> list[Vector3]:
        mn, mx = self.min, self.max
        return [
            Vector3(mn.x, mn.y, mn.z),
            Vector3(mn.x, mn.y, mx.z),
            Vector3(mn.x, mx.y, mn.z),
            Vector3(mn.x, mx.y, mx.z),
            Vector3(mx.x, mn.y, mn.z),
            Vector3(mx.x, mn.y, mx.z),
            Vector3(mx.x, mx.y, mn.z),
            Vector3(mx.x, mx.y, mx.z),
        ]

    @anchor(None, "BBox.cs:LocalToGlobal")
    def local_to_global(self, from_box: "BBox", from_pos, to_pos) -> None:
        fmin, fmax = from_box.min, from_box.max
        self.min = to_pos.local_to_global_from(from_pos, fmin)
        self.max = to_pos.local_to_global_from(from_pos, fmax)
        self.adjust_bbox(to_pos.local_to_global_from(from_pos, Vector3(fmax.x, fmax.y, fmin.z)))
        self.adjust_bbox(to_pos.local_to_global_from(from_pos, Vector3(fmax.x, fmin.y, fmax.z)))
        self.adjust_bbox(to_pos.local_to_global_from(from_pos, Vector3(fmin.x, fmax.y, fmax.z)))
        self.adjust_bbox(to_pos.local_to_global_from(from_pos, Vector3(fmin.x, fmax.y, fmin.z)))
        self.adjust_bbox(to_pos.local_to_global_from(from_pos, Vector3(fmax.x, fmin.y, fmin.z)))
        self.adjust_bbox(to_pos.local_to_global_from(from_pos, Vector3(fmin.x, fmin.y, fmax.z)))

    @anchor(None, "BBox.cs:LocalToLocal")
    def local_to_local(self, from_box: "BBox", from_pos, to_pos) -> None:
        """As LocalToGlobal, into `to_pos`'s local frame (an EnvCell's portals and cell tree)."""
        fmin, fmax = from_box.min, from_box.max
        self.min = to_pos.local_to_local(from_pos, fmin)
        self.max = to_pos.local_to_local(from_pos, fmax)
        self.adjust_bbox(to_pos.local_to_local(from_pos, Vector3(fmax.x, fmax.y, fmin.z)))
        self.adjust_bbox(to_pos.local_to_local(from_pos, Vector3(fmax.x, fmin.y, fmax.z)))
        self.adjust_bbox(to_pos.local_to_local(from_pos, Vector3(fmin.x, fmax.y, fmax.z)))
        self.adjust_bbox(to_pos.local_to_local(from_pos, Vector3(fmin.x, fmax.y, fmin.z)))
        self.adjust_bbox(to_pos.local_to_local(from_pos, Vector3(fmax.x, fmin.y, fmin.z)))
        self.adjust_bbox(to_pos.local_to_local(from_pos, Vector3(fmin.x, fmin.y, fmax.z)))
