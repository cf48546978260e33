"""acconform.port.land: the outdoor world ACE builds from CellLandblock data (LandblockStruct, Landblock, LScape).

The cells themselves are in port/cell/ and LandDefs in port/land_defs.py. Submodules are
imported by name (no re-exports here).
"""
