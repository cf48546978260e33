"""BSPLeaf: Unpack(reader, treeType) -- a BSP leaf as DatLoader reads it (ACE.DatLoader Entity/BSPLeaf.cs).

A physics leaf holds its index, Solid (an int; 1 means solid), a bounding sphere and polygon ids
("if Solid is 0 these values are basically null; still read them" -- they are read all the same).
"""

from __future__ import annotations

from dataclasses import dataclass

from ..anchors import anchor
from .bsp_node import BSP_TYPE_PHYSICS, BSPNode, read_tag
from .sphere import Sphere


@dataclass(slots=True, eq=False)
class BSPLeaf(BSPNode):
    leaf_index: int = 0
    solid: int = 0

    @anchor(None, "ACE.DatLoader/Entity/BSPLeaf.cs:Unpack")
    def unpack(self, reader, tree_type: int) -> None:
        self.type = read_tag(reader)
        self.leaf_index = reader.read_int32()

        if tree_type == BSP_TYPE_PHYSICS:
            self.solid = reader.read_int32()
            self.sphere = Sphere.unpack(reader)
            self.in_polys = []
            num_polys = reader.read_uint32()
            for _ in range(num_polys):
                self.in_polys.append(reader.read_uint16())
