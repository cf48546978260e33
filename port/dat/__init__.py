"""ACE.DatLoader: the readers of the DAT records a scene's static objects are written as (acconform/dat.py).

One module per DatLoader class, each ``Unpack`` line by line, so the port reads the same bytes the
oracle's ACE reads with its own DatLoader: FileTypes GfxObj and SetupModel, and the entities they hold
(CVertexArray, SWVertex, Polygon, BSPTree/BSPNode/BSPLeaf, Plane, Sphere, CylSphere, Frame, ...).
`portal_dat.PortalDat` stands in for DatManager.PortalDat (records by id, no files on disk).
"""
