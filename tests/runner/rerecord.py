"""Re-record a corpus in place with live ACE: every record's scene answered again, the shards keeping their names
and their records' order (so both runtimes' corpora, the same scenes, stay paired by scene key).

    ACE_ASSEMBLY=/path/to/ACE.Server.dll ACE_VERSION=7b47913 python tests/runner/rerecord.py tests/data/corpus/<runtime> [--enter-world] [--shards GLOB]

--shards re-records only the shards whose file names match GLOB (default every shard, *.jsonl.gz).

With --enter-world, a placement through SetPosition whose scene key (oracle.recorded.scene_key, of the scene as it
was) starts with 0-7 becomes a placement through enter_world (flags dropped; get_cell kept), as the strategies now
draw one placement in two; a scene that became the same scene as an earlier record's is dropped (a corpus holds
each scene once). Prints per shard and in all: records, scenes converted, answers changed (by kind), and
for the changed answers each verdict move ("NullReferenceException -> ArgumentOutOfRangeException", "none ->
none", ...), the verdict being an outcome's error or its last tick's."""

from __future__ import annotations

import argparse
import collections
import dataclasses
import gzip
import json
import sys
from pathlib import Path

from acconform import deep
from acconform.case import Record
from acconform.codec import dumps_compact
from acconform.oracle.live import LiveOracle
from acconform.oracle.recorded import scene_key


def verdict(outcome) -> str:
    error = outcome.error or next((t.error for t in reversed(outcome.ticks or ()) if t.error), None)
    return error.split(":", 1)[0] if error else "none"


def converted(scene, enter_world: bool):
    p = scene.mover.placement
    if not enter_world or p is None or p.via != "set_position" or scene_key(scene)[0] not in "01234567":
        return scene, False
    placement = dataclasses.replace(p, flags=0, via="enter_world")
    return scene.replace(mover=dataclasses.replace(scene.mover, placement=placement)), True


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("corpus", type=Path)
    ap.add_argument("--enter-world", action="store_true")
    ap.add_argument("--shards", default="*.jsonl.gz", help="only the shards matching this glob")
    args = ap.parse_args(argv)
    oracle = LiveOracle()
    total = collections.Counter()
    seen = set()
    for shard in sorted(args.corpus.glob(args.shards)):
        kind = shard.name.split("-")[0]
        records = [Record.from_json(json.loads(line)) for line in gzip.open(shard, "rt")]
        c = collections.Counter(records=len(records))
        new = []
        for k in range(0, len(records), 256):
            batch = [converted(r.scene, args.enter_world) for r in records[k:k + 256]]
            answers = oracle.run_many([scene for scene, _ in batch])
            for r, (scene, was_converted), (outcome, _us) in zip(records[k:k + 256], batch, answers):
                key = scene_key(scene)
                if key in seen:
                    c["dropped: the same scene as an earlier record"] += 1
                    continue
                seen.add(key)
                new.append(Record(scene, outcome, oracle.versions))
                c["converted"] += was_converted
                if dumps_compact(r.outcome.to_json()) != dumps_compact(outcome.to_json()):
                    c[f"changed {kind}"] += 1
                    c[f"  {verdict(r.outcome)} -> {verdict(outcome)}" + (" (converted)" if was_converted else "")] += 1
        tmp = shard.with_name(shard.name + ".tmp")
        with gzip.GzipFile(tmp, "wb", compresslevel=9, mtime=0) as f:
            for r in new:
                f.write((deep.retrying(lambda: dumps_compact(r.to_json())) + "\n").encode("utf-8"))
        tmp.replace(shard)
        total.update(c)
        print(shard.name, dict(c), file=sys.stderr, flush=True)
    print(args.corpus, oracle.versions.ace, oracle.versions.runtime)
    for key in sorted(total):
        print(f"{key}: {total[key]}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
