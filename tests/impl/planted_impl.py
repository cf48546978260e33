"""A second implementation for the harness to catch: the port with a planted bug, as a process.

    python tests/impl/planted_impl.py MUTATION [--kinds terrain,bsp] [--crash-on KIND] [--hang-on KIND]
                                      [--garble-on KIND] [--no-handshake]

Speaks acconform.protocol/1 on stdin/stdout like any port under test would. MUTATION names a
planted bug of tests/runner/mutants.py (``none``: the port as it is). ``--crash-on KIND`` exits
with code 3 on a scene of that kind, ``--hang-on KIND`` never answers one, ``--garble-on KIND``
answers one with a line that is not JSON; ``--kinds`` is what its handshake claims to support.
Lives in tests/, outside the package: the harness sees it only through the protocol.
"""

from __future__ import annotations

import argparse
import importlib
import os
import sys
import time
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "runner"))


def main() -> int:
    p = argparse.ArgumentParser()
    p.add_argument("mutation")
    p.add_argument("--kinds", default="terrain,bsp,obstacles")
    p.add_argument("--crash-on", default=None)
    p.add_argument("--hang-on", default=None)
    p.add_argument("--garble-on", default=None)
    p.add_argument("--no-handshake", action="store_true")
    args = p.parse_args()

    from acconform.oracle.recorded import scene_kind
    from acconform.port.run import run_scene
    from acconform.protocol import handshake, serve

    if args.no_handshake:
        time.sleep(3600)
    if args.mutation == "none":
        run = run_scene
    else:
        from mutants import MUTATIONS, load_mutant

        run = load_mutant([m.name for m in MUTATIONS].index(args.mutation))
    traced = importlib.import_module(run.__module__).traced_run  # its own port's tracing (feature trace)

    def answer(scene, mode, runtime):
        kind = scene_kind(scene)
        if kind == args.crash_on:
            os._exit(3)
        if kind == args.hang_on:
            time.sleep(3600)
        if kind == args.garble_on:
            sys.stdout.buffer.write(b"this is not JSON\n")
        return run(scene, mode=mode, runtime=runtime)

    def answer_traced(scene, mode, runtime):
        answer(scene, mode, runtime)  # the same crash, hang and garbling
        return traced(scene, mode, runtime)

    hello = handshake("planted", f"0.0+{args.mutation}")
    hello["kinds"] = args.kinds.split(",")
    return serve(answer, hello=hello, run_traced=answer_traced,
                 trace_anchors=importlib.import_module(run.__module__).traced_anchors())


if __name__ == "__main__":
    sys.exit(main())
