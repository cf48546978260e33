"""BSPNode: Unpack(reader, treeType), ReadNode -- a BSP node as DatLoader reads it (ACE.DatLoader Entity/BSPNode.cs).

The node's type is four ASCII bytes read in reverse ("BPIN" is written N, I, P, B). Which
children follow depends on it: BPnn/BPIn a front child only, BpIN/BpnN a back child only,
BPIN/BPnN both, any other tag (BpIn, BPOL, ...) none. A cell tree's node holds nothing more; a
physics tree's node then holds its bounding sphere and no polygon ids; a drawing tree's node
its sphere and polygon ids. ReadNode peeks at the tag to pick BSPLeaf (LEAF), BSPPortal (PORT,
bsp_portal.py: cell structures' drawing trees hold them) or BSPNode.
"""

from __future__ import annotations

from dataclasses import dataclass

from ..anchors import anchor, harness
from .plane import Plane
from .sphere import Sphere

# ACE.Entity.Enum.BSPType
BSP_TYPE_DRAWING = 0
BSP_TYPE_PHYSICS = 1
BSP_TYPE_CELL = 2


_ASCII = bytes(range(0x80)) + b"?" * 0x80  # Encoding.ASCII: a byte above 0x7F decodes as '?'


@harness(".NET Encoding.ASCII.GetString(bytes) then ACE's string Reverse (a byte above 0x7F reads '?')")
def read_tag(reader) -> str:
    return reader.read_bytes(4).translate(_ASCII).decode("ascii")[::-1]


@dataclass(slots=True, eq=False)
class BSPNode:
    type: str | None = None
    splitting_plane: Plane | None = None
    pos_node: "BSPNode | None" = None
    neg_node: "BSPNode | None" = None
    sphere: Sphere | None = None
    in_polys: list | None = None  # polygon ids (ushort)

    @anchor(None, "ACE.DatLoader/Entity/BSPNode.cs:Unpack")
    def unpack(self, reader, tree_type: int) -> None:
        self.type = read_tag(reader)

        if self.type in ("PORT", "LEAF"):
            raise Exception()  # ACE: these types unpack in their own classes

        self.splitting_plane = Plane.unpack(reader)

        if self.type in ("BPnn", "BPIn"):
            self.pos_node = read_node(reader, tree_type)
        elif self.type in ("BpIN", "BpnN"):
            self.neg_node = read_node(reader, tree_type)
        elif self.type in ("BPIN", "BPnN"):
            self.pos_node = read_node(reader, tree_type)
            self.neg_node = read_node(reader, tree_type)

        if tree_type == BSP_TYPE_CELL:
            return

        self.sphere = Sphere.unpack(reader)

        if tree_type == BSP_TYPE_PHYSICS:
            return

        self.in_polys = []
        num_polys = reader.read_uint32()
        for _ in range(num_polys):
            self.in_polys.append(reader.read_uint16())


@anchor(None, "ACE.DatLoader/Entity/BSPNode.cs:ReadNode")
def read_node(reader, tree_type: int) -> BSPNode:
    # peek at the type, then rewind
    type_ = read_tag(reader)
    reader.position -= 4

    if type_ == "PORT":
        node = bsp_portal.BSPPortal()
    elif type_ == "LEAF":
        node = bsp_leaf.BSPLeaf()
    else:
        node = BSPNode()
    node.unpack(reader, tree_type)
    return node


from . import bsp_leaf, bsp_portal  # noqa: E402  (BSPLeaf and BSPPortal derive from BSPNode)
