"""ACE's Physics/Combat: the target records the TargetManager trades (TargetInfo, TargettedVoyeurInfo)."""
