"""acconform.port: ACE's collision physics, ported to Python line by line (float32-exact).

Modules are named after the retail class they port; every public routine is registered with
its retail and ACE anchors in acconform.port.anchors.
"""
