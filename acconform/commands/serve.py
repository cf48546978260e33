"""acconform serve: the built-in port as an implementation speaking acconform.protocol/1.

Reads requests on stdin and answers on stdout until stdin closes (docs/protocol.md). What a
port in another language implements; `acconform check --impl 'acconform serve'` runs the
differential campaign through it as a separate process.
"""

from __future__ import annotations


def add_arguments(p) -> None:
    from . import add_runtime_argument

    add_runtime_argument(p, "the arithmetic of a request that names no runtime (acconform's requests always name one)")


def run(args) -> int:
    from ..port.run import run_scene, traced_anchors, traced_run
    from ..protocol import serve
    from ..runner import campaign_gc
    from . import runtime_or_default

    with campaign_gc():  # the collector tuned as for an in-process campaign (runner.GC_THRESHOLDS)
        return serve(lambda scene, mode, runtime: run_scene(scene, mode=mode, runtime=runtime),
                     default_runtime=runtime_or_default(args.runtime),
                     run_traced=lambda scene, mode, runtime: traced_run(scene, mode, runtime),
                     trace_anchors=traced_anchors(),
                     run_dat=lambda scene, world, mode, runtime: run_scene(scene, mode=mode, runtime=runtime,
                                                                           world=world))
