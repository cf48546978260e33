"""acconform.port.geom: Polygon/Vertex, Sphere, CylSphere and the physics BSP (ACE Polygon.cs, Sphere.cs, CylSphere.cs, BSP/*.cs)."""
