"""An implementation of acconform.protocol/1 that answers at once: ACE's recorded outcome for the
scene, found by the scene's JSON text as the harness sends it (the text the corpus holds). For
benchmarks/bench_runner.py --impl: it measures the harness, not an implementation.

    PYTHON benchmarks/instant_impl.py CORPUS_DIR
    PYTHON benchmarks/instant_impl.py --fixed      # every scene: Outcome(ok=True), whatever it is
    PYTHON benchmarks/instant_impl.py --fixed --busy MS   # the same after MS milliseconds of work each

With --fixed it answers generated scenes too, all alike (benchmarks/bench_harness.py: the harness's
cost through the protocol, against an oracle that answers the same).

Its handshake is the built-in port's, taken from the acconform of the Python that runs it, so any
install can be measured with it. A scene it does not hold ends it with one line (exit 3).
"""

from __future__ import annotations

import gzip
import sys
from pathlib import Path


def main() -> int:
    import threading

    from acconform.codec import dumps_compact
    from acconform.protocol import handshake

    out = sys.stdout.buffer
    out.write((dumps_compact(handshake("instant", "1")) + "\n").encode())
    out.flush()
    answers: dict[bytes, bytes] = {}
    loaded = threading.Condition()
    done = [False]

    def load() -> None:
        # every shard, in the background from the start, so no request waits for more than what is
        # left to read (read as requests came, a late kind waited for every shard before it: longer
        # than the harness's time limit on a loaded machine)
        for shard in sorted(Path(sys.argv[1]).glob("*-[0-9][0-9][0-9][0-9].jsonl.gz")):
            got = {}
            for line in gzip.open(shard):
                s = line.find(b',"scene":') + 9
                o = line.rfind(b',"outcome":')
                got[line[s:o]] = line[o + 11:line.rstrip().rfind(b"}")]
            with loaded:
                answers.update(got)
                loaded.notify_all()
        with loaded:
            done[0] = True
            loaded.notify_all()

    if sys.argv[1] == "--fixed":
        import time

        from acconform.outcome import Outcome

        fixed = dumps_compact(Outcome(ok=True).to_json()).encode()
        busy = float(sys.argv[3]) / 1000 if sys.argv[2:3] == ["--busy"] else 0.0
        for raw in sys.stdin.buffer:
            if busy:  # an implementation that computes: the CPU busy for that long (not a sleep)
                end = time.perf_counter() + busy
                while time.perf_counter() < end:
                    pass
            out.write(b'{"id":' + raw[6:raw.find(b",")] + b',"outcome":' + fixed + b"}\n")
            out.flush()
        return 0
    threading.Thread(target=load, daemon=True).start()
    for raw in sys.stdin.buffer:
        cut = raw.find(b',"scene":')
        rid, scene = raw[6:raw.find(b",")], raw[cut + 9:raw.rstrip().rfind(b"}")]
        with loaded:
            loaded.wait_for(lambda: scene in answers or done[0])
            answer = answers.get(scene)
        if answer is None:
            sys.stderr.write("instant_impl.py: no recorded answer for this scene\n")
            return 3
        out.write(b'{"id":' + rid + b',"outcome":' + answer + b"}\n")
        out.flush()
    return 0


if __name__ == "__main__":
    sys.exit(main())
