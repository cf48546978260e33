"""The recorded oracle: ACE's answers replayed from a corpus, so CI needs no ACE.

Corpus layout: a directory of gzip'd JSON-lines shards named ``<kind>-<NNNN>.jsonl.gz`` (kind:
terrain, bsp, obstacles, indoor, or ticks for tick scenes over any of them), one `acconform.record/1` document per line (scene, outcome, versions).
Records are keyed by `scene_key`: the SHA-256 of the scene's canonical JSON (sorted keys, no
whitespace), so an equal scene finds its record whatever its name or field order.

Loading reads the shards once and keeps each record's place and versions, not its text (under a
second for the 30,004 committed records): a record's kind comes from its shard's name and its
versions from the head of its line; its line is read from the shard again when it is asked for
(`ShardLines`). `select` picks records (a stratified, seeded sample by kind; a kind; a runtime)
as `Entry`s, and `scenes(entries)` is a lazy sequence that parses each record when it is asked
for, so a replay's first case starts at once and each worker parses only its own records. A
scene handed out by `scenes` is answered by `run` from the record it came from (by identity, or
by key when asked for late); any other scene is looked up by key, in an index of every record
built the first time one is needed. Keying parses the whole corpus (tens of seconds), so each
shard's keys are kept in the user's cache ($XDG_CACHE_HOME/acconform/corpus-keys-1, named by the
shard's SHA-256) and later runs read them instead.

A shard that cannot be read (truncated or corrupt gzip) or a line that is not a record raises
`CorpusCorrupt` naming the shard and the line -- when loading, or when the record is parsed; with
``keep_going`` the bad records are skipped and listed in `RecordedOracle.bad` (or by the runner)
instead. `record` never writes a scene twice, so a corpus holds each scene once.
"""

from __future__ import annotations

import contextlib
import gzip
import hashlib
import json
import os
import random
import re
import tempfile
from collections.abc import Sequence
from dataclasses import dataclass
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
    """The campaign kind (a corpus shard's, `--kinds`'): "ticks" for a tick scene (whatever its
    geometry), else the geometry's kind."""
    return "ticks" if scene.ticks is not None else geometry_kind(scene)


def geometry_kind(scene: Scene) -> str:
    """The kind of the scene's world (what an implementation's handshake lists):
    buildings with buildings, indoor with EnvCells, bsp with a BSP object (or a Setup of BSP parts), obstacles with only spheres and cylspheres, else terrain."""
    if scene.buildings:
        return "buildings"
    if scene.env_cells:
        return "indoor"
    kinds = {"bsp" if o.setup is not None else o.shape.kind for o in scene.objects}  # a setup's parts are BSPs
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
        doc = deep.loads(line)
    except deep.TooDeep as e:
        raise CorpusCorrupt(str(e.in_file(where))) from None
    except ValueError as e:
        raise CorpusCorrupt(f"{where}: not JSON ({e})") from None
    if not isinstance(doc, dict) or doc.get("format") != RECORD_FORMAT or not isinstance(doc.get("scene"), dict):
        raise CorpusCorrupt(f"{where}: not an {RECORD_FORMAT} document with a scene")
    return doc


# the head of a line CorpusWriter wrote: the record's versions come before its scene
_HEAD = re.compile(r'\{"format":"acconform\.record/1","versions":(\{[^{}]*\}),"scene":')


def _versions(v) -> Versions:
    v = v if isinstance(v, dict) else {}
    return Versions(str(v.get("acconform", "")), str(v.get("ace", "")), str(v.get("runtime", "")))


@dataclass(frozen=True, slots=True)
class RecordedText:
    """A record's scene and outcome as the JSON text `record` wrote (what the harness writes for
    them), not parsed: a replay through an implementation process sends the scene as it is and
    compares the answer with the outcome's text first (acconform.protocol, `run_text`)."""

    scene: str
    outcome: str


_OUTCOME = ',"outcome":'

# A tick record of a tick-policy kind (protocol.KIND_FEATURES: motion, doors, movers, missiles, targets; filed
# under "ticks") holds one of its kind's keys in its scene's text: the fields the kind's feature reads, written only
# when set. The first keys say so alone; the second (a MoveToObject or TurnToObject, whose object may be a static)
# only that its scene is to be parsed and asked `protocol.of_kind`. The kinds that need more features first: a scene
# of targets or missiles is one of movers too, and goes to the narrower kind.
_KIND_KEYS: dict[str, tuple[tuple[str, ...], tuple[str, ...]]] = {
    "targets": (('"stick_to":', '"destroy":'), ('"move_to_object":', '"turn_to_object":')),
    "missiles": (('"launch":',), ()),
    "doors": (('"door":',), ()),
    "movers": (('"others":',), ()),
    "motion": (('"motion_table":', '"motion":', '"stop":', '"do_motion":', '"stop_motion":', '"move_to":',
                '"move_to_object":', '"turn_to_heading":', '"turn_to_object":'), ()),
}


class ShardLines:
    """A shard's lines, read again from the shard when a record is asked for: a loaded corpus
    holds each record's place, not its text.

    Keeping every line (385 MB of text for the committed corpus) made loading three times slower
    than reading the shards -- the time went to the memory's first touch -- and every replay paid
    it before its first case. Records are mostly asked for in corpus order (a replay, a worker's
    part of it, a selection, the key index), so one pass through the gzip stream serves them; a
    line before the last one read starts the pass again, and a shard read out of order a second
    time is then kept whole. A process forked after a read never touches its parent's open
    stream: it opens its own."""

    __slots__ = ("path", "_lines", "_at", "_pid", "_recent", "_passes", "_whole", "_broken")

    RECENT = 8  # lines kept, for a record read twice in a row (its text, then its document)

    def __init__(self, path: Path):
        self.path = path
        self._lines = None  # the open pass: an iterator of (line number, line)
        self._at = 0  # the line number it last gave
        self._pid = 0
        self._recent: dict[int, str] = {}
        self._passes = 0
        self._whole: dict[int, str] | None = None  # every line, once the shard is read out of order
        self._broken: tuple[int, CorpusCorrupt] | None = None  # (the last line read, why no more can be)

    def line(self, lineno: int) -> str:
        line = self._recent.get(lineno)
        if line is None and self._whole is not None:
            line = self._whole.get(lineno)
        if line is not None:
            return line
        if self._broken is not None and lineno > self._broken[0]:
            raise self._broken[1]  # cut short since loading: found once, not read again per record
        if self._whole is not None:
            raise self._gone(lineno)
        if self._lines is None or self._pid != os.getpid() or lineno <= self._at:
            self._passes += 1
            self._lines, self._at, self._pid = shard_lines(self.path), 0, os.getpid()
            if self._passes > 2:
                self._whole = {}
        try:
            for n, line in self._lines:
                self._at = n
                if self._whole is not None:
                    self._whole[n] = line
                elif n == lineno:
                    if len(self._recent) >= self.RECENT:
                        self._recent.clear()
                    self._recent[n] = line
                    return line
                elif n > lineno:
                    break
        except CorpusCorrupt as e:
            self._lines = None
            self._broken = (self._at, e)
            raise
        self._lines = None
        line = self._whole.get(lineno) if self._whole is not None else None
        if line is None:
            raise self._gone(lineno)
        return line

    def _gone(self, lineno: int) -> "CorpusCorrupt":
        return CorpusCorrupt(f"{self.path} line {lineno}: no longer there (the shard changed after it was loaded)")


@dataclass(frozen=True, slots=True, eq=False)
class Entry:
    """One corpus record, not parsed yet: its shard and line number, its kind (from the shard's
    name) and the versions it was recorded with; its line is read from the shard when asked for."""

    shard: ShardLines
    lineno: int
    kind: str
    versions: Versions

    @property
    def where(self) -> str:
        return f"{self.shard.path} line {self.lineno}"

    @property
    def line(self) -> str:
        return self.shard.line(self.lineno)

    @property
    def runtime(self) -> str:
        return self.versions.runtime

    def doc(self) -> dict:
        return record_doc(self.line, self.where)

    def text(self) -> RecordedText | None:
        """Its scene's and outcome's text, cut from the line as CorpusWriter lays it out (versions,
        scene, outcome); None for a line laid out otherwise."""
        line = self.line
        head = _HEAD.match(line)
        end = len(line)
        while end and line[end - 1] in " \t\r\n":  # (not rstrip(): that copies the line)
            end -= 1
        cut = line.rfind(_OUTCOME, 0, end)
        if head is None or cut < head.end() or line[end - 1] != "}":
            return None
        return RecordedText(line[head.end():cut], line[cut + len(_OUTCOME):end - 1])

    @property
    def key(self) -> str:
        return _doc_key(self.doc())


class Scenes(Sequence):
    """The scenes of some corpus entries, parsed when asked for (``scenes[i]``, iteration).

    ``scenes[i]`` raises CorpusCorrupt (naming shard and line) for a record that does not parse;
    iteration skips such a record when the oracle keeps going (listing it in `oracle.bad`)."""

    def __init__(self, oracle: "RecordedOracle", entries: list[Entry]):
        self.oracle = oracle
        self.entries = entries

    def __len__(self) -> int:
        return len(self.entries)

    def __getitem__(self, i):
        if isinstance(i, slice):
            return Scenes(self.oracle, self.entries[i])
        return self.oracle._hand_out(self.entries[i])

    def text(self, i: int) -> RecordedText | None:
        """The i-th record's scene and outcome as written, unparsed (None: a line laid out otherwise)."""
        return self.entries[i].text()

    def __iter__(self):
        for e in self.entries:
            try:
                yield self.oracle._hand_out(e)
            except CorpusCorrupt as err:
                self.oracle._bad(err)


class RecordedOracle:
    """ACE's answers from a corpus. `progress(message)` (optional) hears about each shard as it
    loads, and about the key index when one is built."""

    name = "recorded"
    HANDED_OUT = 256  # scenes from `scenes` whose answers are kept until `run` asks for them

    def __init__(self, corpus_dir, *, keep_going: bool = False, progress=None):
        self.corpus_dir = Path(corpus_dir)
        if not self.corpus_dir.is_dir():
            raise CorpusMissing(f"no recorded-oracle corpus at {self.corpus_dir} (expected <kind>-NNNN.jsonl.gz "
                                "shards written by `acconform record`); configure ACE for the live oracle or record one")
        self.keep_going = keep_going
        self.progress = progress
        self.bad: list[str] = []  # what keep_going skipped, each naming shard and line
        self.entries: list[Entry] = []
        self._index: dict[str, Entry] | None = None  # key -> entry, built when first needed
        self._handed: dict[int, tuple[Scene, Entry, dict]] = {}  # id(scene) -> (scene, entry, its outcome)
        self._handed_keys: dict[str, Entry] = {}  # scene key -> entry, of every scene handed out and keyed
        self._unkeyed: list[Entry] = []  # handed out, not keyed yet: keyed when `run` first needs a key
        self._spans: list[tuple[Path, int, int]] = []  # each shard's entries: (shard, first, end)
        versions: set[Versions] = set()
        by_head: dict[str, Versions] = {}  # a line's head names its versions: a corpus has a few heads
        for misnamed in sorted(p for p in self.corpus_dir.glob("*.jsonl.gz") if not SHARD_RE.match(p.name)):
            self._bad(CorpusCorrupt(f"{misnamed}: not read: a shard is named <kind>-NNNN.jsonl.gz (e.g. "
                                    f"terrain-0000.jsonl.gz); rename it"))
        for shard in shards(self.corpus_dir):
            kind = SHARD_RE.match(shard.name)["kind"]
            if progress is not None:
                progress(f"loading {shard.name} ({len(self.entries)} records so far)")
            first = len(self.entries)
            lines = ShardLines(shard)
            try:
                for lineno, line in shard_lines(shard):
                    head = _HEAD.match(line)
                    v = by_head.get(head[1]) if head else None
                    if v is None:
                        where = f"{shard} line {lineno}"
                        try:
                            v = _versions(json.loads(head[1]) if head else record_doc(line, where).get("versions"))
                        except (CorpusCorrupt, ValueError) as e:
                            self._bad(e if isinstance(e, CorpusCorrupt) else CorpusCorrupt(f"{where}: not JSON ({e})"))
                            continue
                        if head:
                            by_head[head[1]] = v
                        versions.add(v)
                    self.entries.append(Entry(lines, lineno, kind, v))
            except CorpusCorrupt as e:
                self._bad(e)
            self._spans.append((shard, first, len(self.entries)))
        if not self.entries:
            raise CorpusMissing(f"the recorded-oracle corpus at {self.corpus_dir} holds no records "
                                "(record some with `acconform record`)")
        vs = sorted(versions, key=lambda v: (v.ace, v.runtime))
        self.versions = vs[0] if len(vs) == 1 else Versions(
            "", "; ".join(sorted({v.ace for v in vs})), "; ".join(sorted({v.runtime for v in vs})))

    def _bad(self, e: CorpusCorrupt) -> None:
        if not self.keep_going:
            raise e
        self.bad.append(str(e))

    def __len__(self) -> int:
        return len(self.entries)

    def runtimes(self) -> list[str]:
        return sorted({e.runtime for e in self.entries})

    # ------------------------------------------------------------ by key (parses every record once)

    def index(self, progress=None) -> dict[str, Entry]:
        """Every entry by scene key, built the first time (it parses every record: tens of seconds
        for the committed corpus); `progress(done, total)` hears every 500 records."""
        if self._index is None:
            if self.progress is not None and progress is None:
                self.progress(f"indexing {len(self.entries)} records by scene key")
            index: dict[str, Entry] = {}
            for shard, first, end in self._spans:
                kept = _keys_file(shard)
                keys = _kept_keys(kept, end - first)
                fresh = keys is None
                if fresh:
                    keys = []
                for i in range(first, end):
                    if progress is not None and i % 500 == 0:
                        progress(i, len(self.entries))
                    e = self.entries[i]
                    if fresh:
                        try:
                            keys.append(_doc_key(e.doc()))
                        except CorpusCorrupt as err:
                            self._bad(err)
                            keys.append(None)
                    if keys[i - first] is not None:
                        index.setdefault(keys[i - first], e)
                if fresh and None not in keys:
                    _keep_keys(kept, keys)
            if progress is not None:
                progress(len(self.entries), len(self.entries))
            self._index = index
        return self._index

    def _keyed(self) -> dict[str, Entry]:
        return self.index()

    def __contains__(self, scene: Scene) -> bool:
        return scene_key(scene) in self._keyed()

    def record(self, scene: Scene) -> Record:
        key = scene_key(scene)
        entry = self._keyed().get(key)
        if entry is None:
            label = f" {scene.name!r}" if scene.name else ""
            raise UnrecordedScene(f"the recorded oracle ({self.corpus_dir}, {len(self)} records) has no answer for "
                                  f"scene{label} (key {key[:16]}); record it with `acconform record` and a live ACE")
        return self._record(entry)

    def _record(self, entry: "Entry | str") -> Record:
        """The record of an entry (or of a scene key)."""
        if isinstance(entry, str):
            entry = self._keyed()[entry]
        try:
            return Record.from_json(entry.doc())
        except InvalidScene as e:
            raise CorpusCorrupt(f"{entry.where}: {e}") from None

    def records(self):
        """Every record, in corpus order."""
        for e in self.entries:
            yield self._record(e)

    # ------------------------------------------------------------ selecting and replaying

    def select(self, *, n: int | None = None, seed: int = 0, kinds=None, runtime: str | None = None,
               unsupported=None, skipped=None) -> list[Entry]:
        """Entries in corpus order: of `kinds`, recorded on `runtime` (its name, e.g. "mono", or a
        full runtime string), and when `n` is given a sample of n stratified by kind (each kind
        gets its share of n, at least one when n allows), drawn with `seed`: each kind's records
        in a seeded order, the first ones taken. A tick-policy kind among `kinds` (motion, doors, movers,
        missiles, targets: filed as "ticks") selects the tick records of that kind (`_tick_kinds`).

        `unsupported(scene) -> reason or None` (an implementation's handshake): with `n`, a record
        whose scene it names is passed over for the next one of its kind, so n are still taken,
        and its reason is counted in `skipped` (a Counter); without `n` nothing is parsed here (but the
        records of a tick-policy kind, to tell whether they are of it)."""
        from ..protocol import of_kind

        tick_kinds = [k for k in _KIND_KEYS if kinds is not None and k in kinds]
        entries = [e for e in self.entries
                   if (kinds is None or e.kind in kinds or tick_kinds and e.kind == "ticks")
                   and (runtime is None or e.runtime == runtime or e.runtime.split(" ", 1)[0] == runtime)]
        group, unsure = {i: e.kind for i, e in enumerate(entries)}, set()
        if tick_kinds:
            entries, group, unsure = self._tick_kinds(entries, tick_kinds, "ticks" in kinds, check=n is None)
        if n is None:
            return entries
        by_kind: dict[str, list[int]] = {}
        for i in range(len(entries)):
            by_kind.setdefault(group[i], []).append(i)
        n = min(n, len(entries))
        shares = {kind: n * len(ix) / len(entries) for kind, ix in by_kind.items()}
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
        chosen: set[int] = set()
        for kind in sorted(by_kind):
            order = rng.sample(by_kind[kind], len(by_kind[kind]))
            got = at = 0
            while got < take[kind] and at < len(order):
                # the records still wanted, next in the seeded order: read in corpus order (one pass
                # through each shard), then taken or passed over in the seeded order
                batch = order[at:at + take[kind] - got]
                at += len(batch)
                verdicts = {}
                if unsupported is not None or unsure.intersection(batch):
                    for i in sorted(batch if unsupported is not None else unsure.intersection(batch)):
                        try:
                            scene = self._hand_out(entries[i], keep=False)
                            if i in unsure and not of_kind(scene, kind):
                                verdicts[i] = False  # its text named the kind's fields, its scene does not need them
                            elif unsupported is not None:
                                verdicts[i] = unsupported(scene)
                        except CorpusCorrupt as err:
                            verdicts[i] = err
                for i in batch:
                    why = verdicts.get(i)
                    if isinstance(why, CorpusCorrupt):
                        self._bad(why)
                        continue
                    if why is False:
                        continue
                    if why:
                        if skipped is not None:
                            skipped[why] += 1
                        continue
                    chosen.add(i)
                    got += 1
        return [e for i, e in enumerate(entries) if i in chosen]

    def _tick_kinds(self, entries: list[Entry], tick_kinds: list[str], ticks: bool, check: bool):
        """(entries, their kinds by index, the indices whose kind is still to be asked) with the tick records sorted
        into the tick-policy kinds asked for by their text's keys (`_KIND_KEYS`): each goes to the first kind it
        surely is, else to the first it may be (or to "ticks" when `ticks` is asked for too, else it is left out).
        With `check` a record that may be of its kind is parsed here and kept only if it is (`of_kind`); else
        it is left to the sample's loop to ask, of the ones it takes."""
        from ..protocol import of_kind

        kept: list[Entry] = []
        group: dict[int, str] = {}
        unsure: set[int] = set()
        shard, lines = None, iter(())
        for e in entries:
            kind, sure = e.kind, True
            if kind == "ticks":
                # each shard read through once, beside its ShardLines (whose passes the replay's reading counts)
                if e.shard is not shard:
                    shard, lines = e.shard, shard_lines(e.shard.path)
                try:
                    line = next((text for n, text in lines if n == e.lineno), None)
                except CorpusCorrupt as err:
                    shard, lines = e.shard, iter(())
                    self._bad(err)
                    continue
                if line is None:
                    self._bad(e.shard._gone(e.lineno))
                    continue
                cut = line.rfind(_OUTCOME)  # the scene's text: an outcome has keys of its own
                kind = next((k for k in tick_kinds if any(line.find(key, 0, cut) >= 0 for key in _KIND_KEYS[k][0])), None)
                if kind is None:
                    kind = next((k for k in tick_kinds if any(line.find(key, 0, cut) >= 0 for key in _KIND_KEYS[k][1])),
                                None)
                    sure = kind is None
                if not sure and check:
                    try:
                        sure, kind = True, kind if of_kind(self._hand_out(e, keep=False), kind) else None
                    except CorpusCorrupt as err:
                        self._bad(err)
                        continue
                kind = kind or ("ticks" if ticks else None)
                if kind is None:
                    continue
            if not sure:
                unsure.add(len(kept))
            group[len(kept)] = kind
            kept.append(e)
        return kept, group, unsure

    def scenes(self, entries=None) -> Scenes:
        """The scenes of `entries` (default: every record), in their order, parsed when asked for."""
        return Scenes(self, list(self.entries) if entries is None else list(entries))

    def _hand_out(self, entry: Entry, keep: bool = True) -> Scene:
        """The entry's scene, parsed; kept (with the entry's answer) for `run` when `keep`. Its
        outcome is read here too: a record without a readable answer (none, a NaN written as a
        number) is an unreadable record, refused or skipped as one, never a difference with ACE."""
        doc = entry.doc()
        try:
            record = deep.retrying(Record.from_json, doc)
        except InvalidScene as e:
            raise CorpusCorrupt(f"{entry.where}: {e}") from None
        scene, outcome = record.scene, record.outcome
        if keep:
            self._unkeyed.append(entry)  # keyed only if `run` is asked for it other than as handed out
            if len(self._handed) >= self.HANDED_OUT:
                del self._handed[next(iter(self._handed))]
            self._handed[id(scene)] = (scene, entry, outcome)
        return scene

    def run(self, scene: Scene) -> Outcome:
        handed = self._handed.pop(id(scene), None)
        if handed is not None and handed[0] is scene:
            return handed[2]
        for unkeyed in self._unkeyed:
            self._handed_keys[_doc_key(unkeyed.doc())] = unkeyed
        self._unkeyed.clear()
        entry = self._handed_keys.get(scene_key(scene))  # handed out, but asked for late or as an equal copy
        if entry is not None:
            return self._record(entry).outcome
        return self.record(scene).outcome


def _doc_key(doc) -> str:
    scene = dict(doc["scene"])
    scene.pop("name", None)
    # the same canonical form scene_key hashes: the stored scene JSON is what Scene.to_json wrote
    return hashlib.sha256(_canonical(scene).encode()).hexdigest()


# the cached key lists (`_kept_keys`) are named by this and by the shard's bytes: change it when the
# key's canonical form (`_canonical`) changes
KEYS_CACHE = "corpus-keys-1"


def _keys_file(shard: Path) -> Path | None:
    """Where a shard's keys are kept: named by the shard's SHA-256 (None if the shard cannot be read)."""
    from .config import cache_dir

    try:
        return cache_dir() / KEYS_CACHE / (hashlib.sha256(shard.read_bytes()).hexdigest() + ".json")
    except OSError:
        return None


def _kept_keys(kept: Path | None, n: int) -> list[str] | None:
    """The scene keys of a shard's n records, as a run before this one found them, or None. Keying
    parses and re-serialises every scene (tens of seconds for the committed corpus); a shard's keys
    follow from its bytes alone, so they are kept in the user's cache under the shard's SHA-256."""
    try:
        keys = json.loads(kept.read_text()) if kept is not None else None
    except (OSError, ValueError):
        return None
    ok = isinstance(keys, list) and len(keys) == n and all(isinstance(k, str) and len(k) == 64 for k in keys)
    return keys if ok else None


def _keep_keys(kept: Path | None, keys: list[str]) -> None:
    """Keep a shard's keys for the next run; a cache that cannot be written costs only that."""
    if kept is None:
        return
    tmp = None
    try:
        kept.parent.mkdir(parents=True, exist_ok=True)
        fd, tmp = tempfile.mkstemp(dir=kept.parent, suffix=".tmp")
        with os.fdopen(fd, "w") as f:
            json.dump(keys, f)
        os.replace(tmp, kept)  # whole or not at all, whatever other processes key the same shard
    except OSError:
        if tmp is not None:
            with contextlib.suppress(OSError):
                os.unlink(tmp)


def _canonical(scene_json: dict) -> str:
    """The canonical JSON a scene key hashes (a deep BSP's on a deep stack)."""
    return deep.retrying(json.dumps, scene_json, sort_keys=True, separators=(",", ":"))


class CorpusWriteFailed(AcconformError):
    """A shard could not be written (a full disk): the shards finished before it are kept, the
    unfinished ones removed; the message says so and names the corpus."""


class CorpusWriter:
    """Appends records to a corpus as new shards (never rewrites an existing shard). A shard is
    written as <name>.tmp and renamed when finished, so a shard that cannot be finished (the disk
    filled, the writer was stopped) never appears half-written: its .tmp is removed."""

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
            try:
                f = gzip.GzipFile(path.with_name(path.name + ".tmp"), "wb", compresslevel=9, mtime=0)
            except OSError as e:
                raise self._failed(e) from None
            count = 0
        self._open[kind] = (f, path, count)
        line = (deep.retrying(lambda: dumps_compact(record.to_json())) + "\n").encode("utf-8")
        try:
            f.write(line)
        except OSError as e:
            self._abandon(kind)
            raise self._failed(e) from None
        self._open[kind] = (f, path, count + 1)
        self.written[kind] = self.written.get(kind, 0) + 1

    def _close(self, kind: str) -> None:
        f, path, _ = self._open[kind]
        try:
            f.close()
            path.with_name(path.name + ".tmp").replace(path)
        except OSError as e:
            self._abandon(kind)
            raise self._failed(e) from None
        del self._open[kind]

    def _abandon(self, kind: str) -> None:
        """Remove a shard that cannot be finished (its .tmp)."""
        f, path, _ = self._open.pop(kind)
        try:
            f.close()
        except OSError:
            pass  # what it could not write is lost with the shard
        path.with_name(path.name + ".tmp").unlink(missing_ok=True)

    def _failed(self, e: OSError) -> CorpusWriteFailed:
        return CorpusWriteFailed(f"{self.dir}: cannot write a shard ({e.strerror or e}); the shards finished are "
                                 "kept, a shard that could not be finished is removed: make room and record again "
                                 "(the scenes already recorded are skipped)")

    def close(self) -> None:
        """Finish every open shard; CorpusWriteFailed (after trying them all) when one cannot be."""
        failed = None
        for kind in list(self._open):
            try:
                self._close(kind)
            except CorpusWriteFailed as e:
                failed = failed or e
        if failed is not None:
            raise failed

    def __enter__(self):
        return self

    def __exit__(self, exc_type, exc, tb):
        try:
            self.close()  # on Ctrl-C too: what was recorded is kept
        except CorpusWriteFailed:
            if exc_type is None:
                raise
