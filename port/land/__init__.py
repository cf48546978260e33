"""acconform.port.land: the outdoor world ACE builds from CellLandblock data (LandDefs, LandblockStruct, Landblock, LandCell, LScape).

Submodules are imported by name (no re-exports here), so frame.py can import land_defs
without pulling in the landblock code.
"""
