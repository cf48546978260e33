"""PortalPoly: Unpack -- a drawing-BSP portal node's (portal index, polygon id) pair (ACE.DatLoader Entity/PortalPoly.cs)."""

from __future__ import annotations

from dataclasses import dataclass

from ..anchors import anchor


@dataclass(slots=True)
class PortalPoly:
    portal_index: int = 0  # short
    polygon_id: int = 0  # short

    @staticmethod
    @anchor(None, "ACE.DatLoader/Entity/PortalPoly.cs:Unpack")
    def unpack(reader) -> "PortalPoly":
        p = PortalPoly()
        p.portal_index = reader.read_int16()
        p.polygon_id = reader.read_int16()
        return p
