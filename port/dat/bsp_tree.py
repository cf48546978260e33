"""BSPTree: Unpack(reader, treeType) -- the root node, read by BSPNode.ReadNode (ACE.DatLoader Entity/BSPTree.cs)."""

from __future__ import annotations

from dataclasses import dataclass, field

from ..anchors import anchor
from .bsp_node import BSPNode, read_node


@dataclass(slots=True, eq=False)
class BSPTree:
    root_node: BSPNode = field(default_factory=BSPNode)  # `new BSPNode()` until unpacked

    @anchor(None, "ACE.DatLoader/Entity/BSPTree.cs:Unpack")
    def unpack(self, reader, tree_type: int) -> None:
        self.root_node = read_node(reader, tree_type)
