"""ACE's Physics/Animation: the motion layer (motion tables, sequences, animations, the motion interpreter)."""
