"""Issue 44: a corpus's tick scenes in ACE's server mode, three in four (as the strategies draw them), re-recorded in place.

    ACE_ASSEMBLY=/path/to/ACE.Server.dll ACE_VERSION=7b47913 python tests/runner/server_mode_ticks.py tests/data/corpus/<runtime>

A client-mode tick record whose scene key (oracle.recorded.scene_key, of the client scene) does not start with
0-3 gets its scene in engine mode server and live ACE's answer for it; the others stay as they are. The shards
keep their names and their records' order, so both runtimes' corpora (the same scenes) stay paired. Prints
per shard how many scenes were converted and how many of their answers changed (and of those, how many were
errors before and are errors now)."""
import collections
import gzip
import json
import sys
from pathlib import Path
from acconform.case import Record
from acconform.codec import dumps_compact
from acconform import deep
from acconform.oracle.live import LiveOracle
from acconform.oracle.recorded import scene_key

corpus = Path(sys.argv[1])
oracle = LiveOracle()
c = collections.Counter()
for shard in sorted(corpus.glob("ticks-*.jsonl.gz")):
    records = [Record.from_json(json.loads(line)) for line in gzip.open(shard, "rt")]
    out = []
    todo = [(i, r) for i, r in enumerate(records) if r.scene.engine_mode == "client" and scene_key(r.scene)[0] not in "0123"]
    new = {}
    for k in range(0, len(todo), 256):
        batch = [r.scene.replace(engine_mode="server") for _, r in todo[k:k + 256]]
        for (i, r), scene, (outcome, _us) in zip(todo[k:k + 256], batch, oracle.run_many(batch)):
            new[i] = Record(scene, outcome, oracle.versions)
            c["converted"] += 1
            old_o = dumps_compact(r.outcome.to_json()); new_o = dumps_compact(outcome.to_json())
            if old_o != new_o:
                c["answer_changed"] += 1
                if r.outcome.error is not None or any(t.error for t in (r.outcome.ticks or ())):
                    c["was_error"] += 1
                if outcome.error is not None or any(t.error for t in (outcome.ticks or ())):
                    c["is_error"] += 1
    c["records"] += len(records)
    tmp = shard.with_name(shard.name + ".tmp")
    with gzip.GzipFile(tmp, "wb", compresslevel=9, mtime=0) as f:
        for i, r in enumerate(records):
            f.write((deep.retrying(lambda: dumps_compact(new.get(i, r).to_json())) + "\n").encode("utf-8"))
    tmp.replace(shard)
    print(shard.name, dict(c), file=sys.stderr)
print(corpus, oracle.versions.ace, oracle.versions.runtime, dict(c))
