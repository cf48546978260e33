"""BSPPortal: Unpack(reader, treeType) -- a "PORT" node as DatLoader reads it (ACE.DatLoader Entity/BSPPortal.cs).

A portal node always has both children; a drawing tree's portal node then holds its bounding
sphere, polygon ids and portal polygons. Cell structures' drawing trees hold them.
"""

from __future__ import annotations

from dataclasses import dataclass, field

from ..anchors import anchor
from .bsp_node import BSP_TYPE_DRAWING, BSPNode, read_node, read_tag
from .plane import Plane
from .portal_poly import PortalPoly
from .sphere import Sphere
from .unpackable_extensions import unpack_list_fixed


@dataclass(slots=True, eq=False)
class BSPPortal(BSPNode):
    in_portals: list = field(default_factory=list)  # PortalPoly

    @anchor(None, "ACE.DatLoader/Entity/BSPPortal.cs:Unpack")
    def unpack(self, reader, tree_type: int) -> None:
        self.type = read_tag(reader)
        self.splitting_plane = Plane.unpack(reader)
        self.pos_node = read_node(reader, tree_type)
        self.neg_node = read_node(reader, tree_type)

        if tree_type == BSP_TYPE_DRAWING:
            self.sphere = Sphere.unpack(reader)

            num_polys = reader.read_uint32()
            num_portals = reader.read_uint32()

            self.in_polys = []
            for _ in range(num_polys):
                self.in_polys.append(reader.read_uint16())

            self.in_portals.extend(unpack_list_fixed(reader, PortalPoly.unpack, num_portals))
