"""acconform.port.transition: ACE's Transition machinery (Transition, SpherePath, CollisionInfo, ObjectInfo, CellArray)."""
