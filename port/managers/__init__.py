"""ACE's Physics/Managers as the motion layer reads them: MovementManager, MotionTableManager,
MoveToManager, StickyManager, PositionManager, ConstraintManager, InterpolationManager,
TargetManager, ServerObjectManager, and ScriptManager (Physics/Scripts); one module per ACE file."""
