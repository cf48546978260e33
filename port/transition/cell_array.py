"""CellArray: SetStatic, SetDynamic, add_cell, remove_cell -- over a .NET Dictionary<uint, ObjCell>.

ACE's Common/CellArray.cs. Its Cells is a .NET Dictionary, whose Values enumerate in entry
order: insertion order, except that a removed entry's slot is reused by the next add (the most
recently freed slot first). `NetDictionary` reproduces that order. ACE never clears Cells during
a transition (find_cell_list only resets NumCells and AddedOutside), so cells from earlier steps
stay and are visited again; the port keeps that.
"""

from __future__ import annotations

from dataclasses import dataclass, field

from ..anchors import anchor, harness


class NetDictionary:
    """The iteration order of System.Collections.Generic.Dictionary (entries array + free list)."""

    __slots__ = ("_entries", "_index", "_free")

    def __init__(self):
        self._entries: list = []  # [key, value] or None for a free slot
        self._index: dict = {}
        self._free: list[int] = []  # freed slots, the last freed reused first

    def __len__(self) -> int:
        return len(self._index)

    def __contains__(self, key) -> bool:
        return key in self._index

    def __getitem__(self, key):
        return self._entries[self._index[key]][1]

    @harness(".NET Dictionary.Add: a free slot (last freed first) or a new entry")
    def add(self, key, value) -> None:
        if key in self._index:
            raise KeyError(f"An item with the same key has already been added. Key: {key}")
        if self._free:
            slot = self._free.pop()
            self._entries[slot] = [key, value]
        else:
            slot = len(self._entries)
            self._entries.append([key, value])
        self._index[key] = slot

    @harness(".NET Dictionary's indexer set (dict[key] = value): the key's entry in place, or Add")
    def set(self, key, value) -> None:
        slot = self._index.get(key)
        if slot is None:
            self.add(key, value)
        else:
            self._entries[slot][1] = value

    @harness(".NET Dictionary's enumerator: its KeyValuePairs in entry order")
    def items(self) -> list:
        """``foreach (var kvp in dict)`` (a snapshot list of (key, value), in .NET order)."""
        return [(e[0], e[1]) for e in self._entries if e is not None]

    @harness(".NET Dictionary.Remove: the entry's slot joins the free list")
    def remove(self, key) -> bool:
        slot = self._index.pop(key, None)
        if slot is None:
            return False
        self._entries[slot] = None
        self._free.append(slot)
        return True

    @harness(".NET Dictionary.Keys in entry order")
    def keys(self) -> list:
        return [e[0] for e in self._entries if e is not None]

    @harness(".NET Dictionary.Values in entry order")
    def values(self) -> list:
        """``Cells.Values`` enumerated now (a snapshot list, in .NET order)."""
        return [e[1] for e in self._entries if e is not None]

    @harness(".NET Enumerable.ElementAt over Dictionary.Values")
    def value_at(self, i: int):
        """``Cells.Values.ElementAt(i)``."""
        if not self._free:  # no free slot: the entries are the values, in order
            return self._entries[i][1]
        for e in self._entries:
            if e is not None:
                if i == 0:
                    return e[1]
                i -= 1
        raise IndexError("ElementAt index out of range")


@dataclass(slots=True)
class CellArray:
    added_outside: bool = False
    load_cells: bool = False
    cells: NetDictionary = field(default_factory=NetDictionary)
    num_cells: int = 0
    # the port's, not ACE's: the key of the last add_all_outside_cells replayed into `cells` since
    # the last remove_cell (land_cell.add_all_outside_cells_replayed: replaying it again adds nothing)
    replayed: tuple | None = None

    @anchor("CELLARRAY::SetStatic", "CellArray.cs:SetStatic")
    def set_static(self) -> None:
        self.added_outside = False
        self.load_cells = False
        self.num_cells = 0

    @anchor("CELLARRAY::SetDynamic", "CellArray.cs:SetDynamic")
    def set_dynamic(self) -> None:
        self.added_outside = False
        self.load_cells = True
        self.num_cells = 0

    @anchor("CELLARRAY::add_cell", "CellArray.cs:add_cell")
    def add_cell(self, cell_id: int, cell) -> None:
        if cell_id not in self.cells._index:  # `cell_id in self.cells`, without a Python-level call
            self.cells.add(cell_id, cell)
            self.num_cells += 1

    @anchor("CELLARRAY::remove_cell", "CellArray.cs:remove_cell")
    def remove_cell(self, cell) -> None:
        if cell.id in self.cells:
            self.replayed = None
            self.cells.remove(cell.id)
            self.num_cells -= 1
