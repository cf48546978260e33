"""The recorded oracle: ACE's answers replayed from a corpus, so CI needs no ACE.

Corpus layout: a directory of gzip'd JSON-lines shards named ``<kind>-<NNNN>.jsonl.gz`` (kind:
terrain, bsp, obstacles, indoor), one `acconform.record/1` document per line (scene, outcome, versions).
Records are keyed by `scene_key`: the SHA-256 of the scene's canonical JSON (sorted keys, no
whitespace), so an equal scene finds its record whatever its name or field order.

A shard that cannot be read (truncated or corrupt gzip) or a line that is not a record raises
`CorpusCorrupt` naming the shard and the line; with ``keep_going`` the bad records are skipped
and listed in `RecordedOracle.bad` instead. Records are parsed lazily (loading keeps each line);
`select` picks a stratified, seeded sample by kind (and filters by kind and runtime) before any
scene is parsed.
"""

from __future__ import annotations

import gzip
import hashlib
import json
import random
import re
from pathlib import Path

from ..case import RECORD_FORMAT, Record, Versions, jsonl_lines
from .. import deep
from ..codec import dumps_compact
from ..errors import AcconformError, InvalidScene
from ..outcome import Outcome
from ..scene import Scene

SHARD_RE = re.compile(r"^(?P<kind>[a-z0-9_]+)-(?P<n>\d{4,})\.jsonl\.gz$")
SHARD_SIZE = 2500


class UnrecordedScene(AcconformError, KeyError):
    """The recorded oracle has no answer for this scene."""

    def __str__(self):
        return self.args[0]


class CorpusMissing(AcconformError):
    """The corpus directory is absent or holds no records."""


class CorpusCorrupt(AcconformError):
    """A shard cannot be read, or one of its lines is not a record; the message names shard and line."""


def scene_key(scene: Scene) -> str:
    doc = deep.retrying(scene.to_json)
    doc.pop("name", None)  # a scene's name is a label, not part of the physics
    return hashlib.sha256(_canonical(doc).encode()).hexdigest()


def scene_kind(scene: Scene) -> str:
    if scene.env_cells:
        return "indoor"
    kinds = {o.shape.kind for o in scene.objects}
    if "bsp" in kinds:
        return "bsp"
    if kinds:
        return "obstacles"
    return "terrain"


def shards(corpus_dir: Path) -> list[Path]:
    return sorted(p for p in Path(corpus_dir).glob("*.jsonl.gz") if SHARD_RE.match(p.name))


def shard_lines(shard: Path):
    """(line number, line) for each non-empty line of a shard; CorpusCorrupt names the shard and the
    last line read when the gzip stream is truncated or corrupt."""
    try:
        yield from jsonl_lines(shard)
    except InvalidScene as e:
        raise CorpusCorrupt(str(e)) from None


def record_doc(line: str, where: str) -> dict:
    """A corpus line's JSON, checked enough to key it (a record with a scene); CorpusCorrupt otherwise."""
    try:
        doc = deep.retrying(json.loads, line)
    except ValueError as e:
        raise CorpusCorrupt(f"{where}: not JSON ({e})") from None
    if not isinstance(doc, dict) or doc.get("format") != RECORD_FORMAT or not isinstance(doc.get("scene"), dict):
        raise CorpusCorrupt(f"{where}: not an {RECORD_FORMAT} document with a scene")
    return doc


class RecordedOracle:
    """ACE's answers from a corpus. `progress(message)` (optional) hears about each shard as it loads."""

    name = "recorded"

    def __init__(self, corpus_dir, *, keep_going: bool = False, progress=None):
        self.corpus_dir = Path(corpus_dir)
        if not self.corpus_dir.is_dir():
            raise CorpusMissing(f"no recorded-oracle corpus at {self.corpus_dir} (expected <kind>-NNNN.jsonl.gz "
                                "shards written by `acconform record`); configure ACE for the live oracle or record one")
        self.keep_going = keep_going
        self.bad: list[str] = []  # what keep_going skipped, each naming shard and line
        self._lines: dict[str, str] = {}
        self._where: dict[str, tuple[str, str, str]] = {}  # key -> ("shard line N", kind, runtime)
        self._versions: set[Versions] = set()
        for misnamed in sorted(p for p in self.corpus_dir.glob("*.jsonl.gz") if not SHARD_RE.match(p.name)):
            self._bad(CorpusCorrupt(f"{misnamed}: not read: a shard is named <kind>-NNNN.jsonl.gz (e.g. "
                                    f"terrain-0000.jsonl.gz); rename it"))
        for shard in shards(self.corpus_dir):
            kind = SHARD_RE.match(shard.name)["kind"]
            if progress is not None:
                progress(f"loading {shard.name} ({len(self._lines)} records so far)")
            try:
                for lineno, line in shard_lines(shard):
                    where = f"{shard} line {lineno}"
                    try:
                        doc = record_doc(line, where)
                    except CorpusCorrupt as e:
                        self._bad(e)
                        continue
                    key = _doc_key(doc)
                    v = doc.get("versions") if isinstance(doc.get("versions"), dict) else {}
                    version = Versions(str(v.get("acconform", "")), str(v.get("ace", "")), str(v.get("runtime", "")))
                    self._lines[key] = line
                    self._where[key] = (where, kind, version.runtime)
                    self._versions.add(version)
            except CorpusCorrupt as e:
                self._bad(e)
        if not self._lines:
            raise CorpusMissing(f"the recorded-oracle corpus at {self.corpus_dir} holds no records "
                                "(record some with `acconform record`)")
        vs = sorted(self._versions, key=lambda v: (v.ace, v.runtime))
        self.versions = vs[0] if len(vs) == 1 else Versions(
            "", "; ".join(sorted({v.ace for v in vs})), "; ".join(sorted({v.runtime for v in vs})))

    def _bad(self, e: CorpusCorrupt) -> None:
        if not self.keep_going:
            raise e
        self.bad.append(str(e))

    def __len__(self) -> int:
        return len(self._lines)

    def runtimes(self) -> list[str]:
        return sorted({rt for _, _, rt in self._where.values()})

    def select(self, *, n: int | None = None, seed: int = 0, kinds=None, runtime: str | None = None) -> list[str]:
        """Record keys in corpus order: of `kinds`, recorded on `runtime` (its name, e.g. "mono", or
        a full runtime string), and when `n` is given a sample of n stratified by kind (each kind
        gets its share of n, at least one when n allows), drawn with `seed`."""
        keys = [k for k, (_, kind, rt) in self._where.items()
                if (kinds is None or kind in kinds)
                and (runtime is None or rt == runtime or rt.split(" ", 1)[0] == runtime)]
        if n is None or n >= len(keys):
            return keys
        by_kind: dict[str, list[str]] = {}
        for k in keys:
            by_kind.setdefault(self._where[k][1], []).append(k)
        shares = {kind: n * len(ks) / len(keys) for kind, ks in by_kind.items()}
        take = {kind: int(x) for kind, x in shares.items()}
        # the cases left go to the largest remainders; then every kind gets one if n allows
        for kind in sorted(by_kind, key=lambda kind: (int(shares[kind]) - shares[kind], kind))[:n - sum(take.values())]:
            take[kind] += 1
        if n >= len(by_kind):
            for kind in by_kind:
                if take[kind] == 0:
                    take[max(take, key=take.get)] -= 1
                    take[kind] = 1
        rng = random.Random(seed)
        chosen = set()
        for kind in sorted(by_kind):
            chosen.update(rng.sample(by_kind[kind], min(take[kind], len(by_kind[kind]))))
        return [k for k in keys if k in chosen]

    def __contains__(self, scene: Scene) -> bool:
        return scene_key(scene) in self._lines

    def record(self, scene: Scene) -> Record:
        key = scene_key(scene)
        line = self._lines.get(key)
        if line is None:
            label = f" {scene.name!r}" if scene.name else ""
            raise UnrecordedScene(f"the recorded oracle ({self.corpus_dir}, {len(self)} records) has no answer for "
                                  f"scene{label} (key {key[:16]}); record it with `acconform record` and a live ACE")
        return self._record(key)

    def _record(self, key: str) -> Record:
        try:
            return deep.retrying(lambda: Record.from_json(json.loads(self._lines[key])))
        except InvalidScene as e:
            raise CorpusCorrupt(f"{self._where[key][0]}: {e}") from None

    def records(self):
        """Every record, in corpus order."""
        for key in self._lines:
            yield self._record(key)

    def run(self, scene: Scene) -> Outcome:
        return self.record(scene).outcome

    def scenes(self, keys=None, progress=None):
        """The recorded scenes of `keys` (default: every one), in corpus order.

        A record whose scene does not read raises CorpusCorrupt naming shard and line; with
        keep_going it is skipped and listed in `bad`. `progress(done, total)` hears every 1,000.
        """
        keys = list(self._lines) if keys is None else list(keys)
        for i, key in enumerate(keys):
            if progress is not None and i % 1000 == 0:
                progress(i, len(keys))
            try:
                yield deep.retrying(lambda: Scene.from_json(json.loads(self._lines[key])["scene"], "scene"))
            except InvalidScene as e:
                self._bad(CorpusCorrupt(f"{self._where[key][0]}: {e}"))


def _doc_key(doc) -> str:
    scene = dict(doc["scene"])
    scene.pop("name", None)
    # the same canonical form scene_key hashes: the stored scene JSON is what Scene.to_json wrote
    return hashlib.sha256(_canonical(scene).encode()).hexdigest()


def _canonical(scene_json: dict) -> str:
    """The canonical JSON a scene key hashes (a deep BSP's on a deep stack)."""
    return deep.retrying(json.dumps, scene_json, sort_keys=True, separators=(",", ":"))


class CorpusWriter:
    """Appends records to a corpus as new shards (never rewrites an existing shard)."""

    def __init__(self, corpus_dir, shard_size: int = SHARD_SIZE):
        self.dir = Path(corpus_dir)
        self.dir.mkdir(parents=True, exist_ok=True)
        self.shard_size = shard_size
        self._open: dict[str, tuple[gzip.GzipFile, Path, int]] = {}
        self.written: dict[str, int] = {}

    def _next_index(self, kind: str) -> int:
        used = [int(m["n"]) for p in self.dir.iterdir() if (m := SHARD_RE.match(p.name)) and m["kind"] == kind]
        used += [int(SHARD_RE.match(p.name)["n"]) for _, p, _ in self._open.values() if SHARD_RE.match(p.name)["kind"] == kind]
        return max(used, default=-1) + 1

    def add(self, record: Record) -> None:
        kind = scene_kind(record.scene)
        f, path, count = self._open.get(kind, (None, None, 0))
        if f is None or count >= self.shard_size:
            if f is not None:
                self._close(kind)
            path = self.dir / f"{kind}-{self._next_index(kind):04d}.jsonl.gz"
            tmp = path.with_name(path.name + ".tmp")
            f = gzip.GzipFile(tmp, "wb", compresslevel=9, mtime=0)
            count = 0
        f.write((deep.retrying(lambda: dumps_compact(record.to_json())) + "\n").encode("utf-8"))
        self._open[kind] = (f, path, count + 1)
        self.written[kind] = self.written.get(kind, 0) + 1

    def _close(self, kind: str) -> None:
        f, path, _ = self._open.pop(kind)
        f.close()
        path.with_name(path.name + ".tmp").replace(path)

    def close(self) -> None:
        for kind in list(self._open):
            self._close(kind)

    def __enter__(self):
        return self

    def __exit__(self, *exc):
        self.close()
