"""The recorded oracle: ACE's answers replayed from a corpus, so CI needs no ACE.

Corpus layout: a directory of gzip'd JSON-lines shards named ``<kind>-<NNNN>.jsonl.gz`` (kind:
terrain, bsp, obstacles), one `acconform.record/1` document per line (scene, outcome, versions).
Records are keyed by `scene_key`: the SHA-256 of the scene's canonical JSON (sorted keys, no
whitespace), so an equal scene finds its record whatever its name or field order.
"""

from __future__ import annotations

import gzip
import hashlib
import json
import re
from pathlib import Path

from ..case import Record, Versions
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


def scene_key(scene: Scene) -> str:
    doc = scene.to_json()
    doc.pop("name", None)  # a scene's name is a label, not part of the physics
    return hashlib.sha256(json.dumps(doc, sort_keys=True, separators=(",", ":")).encode()).hexdigest()


def scene_kind(scene: Scene) -> str:
    kinds = {o.shape.kind for o in scene.objects}
    if "bsp" in kinds:
        return "bsp"
    if kinds:
        return "obstacles"
    return "terrain"


def shards(corpus_dir: Path) -> list[Path]:
    return sorted(p for p in Path(corpus_dir).glob("*.jsonl.gz") if SHARD_RE.match(p.name))


def iter_records(corpus_dir: Path):
    for shard in shards(corpus_dir):
        with gzip.open(shard, "rt", encoding="utf-8") as f:
            for lineno, line in enumerate(f, 1):
                if not line.strip():
                    continue
                try:
                    yield Record.from_json(json.loads(line))
                except (ValueError, InvalidScene) as e:
                    raise InvalidScene("", f"bad record at line {lineno}: {e}", str(shard)) from None


class RecordedOracle:
    name = "recorded"

    def __init__(self, corpus_dir):
        self.corpus_dir = Path(corpus_dir)
        if not self.corpus_dir.is_dir():
            raise CorpusMissing(f"no recorded-oracle corpus at {self.corpus_dir} (expected <kind>-NNNN.jsonl.gz "
                                "shards written by `acconform record`); configure ACE for the live oracle or record one")
        self._lines: dict[str, str] = {}
        self._versions: set[Versions] = set()
        for shard in shards(self.corpus_dir):
            with gzip.open(shard, "rt", encoding="utf-8") as f:
                for line in f:
                    if line.strip():
                        doc = json.loads(line)
                        self._lines[_doc_key(doc)] = line
                        v = doc.get("versions") or {}
                        self._versions.add(Versions(v.get("acconform", ""), v.get("ace", ""), v.get("runtime", "")))
        if not self._lines:
            raise CorpusMissing(f"the recorded-oracle corpus at {self.corpus_dir} holds no records "
                                "(record some with `acconform record`)")
        vs = sorted(self._versions, key=lambda v: (v.ace, v.runtime))
        self.versions = vs[0] if len(vs) == 1 else Versions(
            "", "; ".join(sorted({v.ace for v in vs})), "; ".join(sorted({v.runtime for v in vs})))

    def __len__(self) -> int:
        return len(self._lines)

    def __contains__(self, scene: Scene) -> bool:
        return scene_key(scene) in self._lines

    def record(self, scene: Scene) -> Record:
        key = scene_key(scene)
        line = self._lines.get(key)
        if line is None:
            label = f" {scene.name!r}" if scene.name else ""
            raise UnrecordedScene(f"the recorded oracle ({self.corpus_dir}, {len(self)} records) has no answer for "
                                  f"scene{label} (key {key[:16]}); record it with `acconform record` and a live ACE")
        return Record.from_json(json.loads(line))

    def run(self, scene: Scene) -> Outcome:
        return self.record(scene).outcome

    def scenes(self):
        """Every recorded scene, in corpus order."""
        for line in self._lines.values():
            yield Scene.from_json(json.loads(line)["scene"])

    def records(self):
        for line in self._lines.values():
            yield Record.from_json(json.loads(line))


def _doc_key(doc) -> str:
    scene = dict(doc["scene"])
    scene.pop("name", None)
    # the same canonical form scene_key hashes: the stored scene JSON is what Scene.to_json wrote
    return hashlib.sha256(json.dumps(scene, sort_keys=True, separators=(",", ":")).encode()).hexdigest()


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
        f.write((dumps_compact(record.to_json()) + "\n").encode("utf-8"))
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
