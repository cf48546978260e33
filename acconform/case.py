"""Case files (a shrunk difference, replayable) and oracle records (ACE's answer to a scene).

``acconform.case/3``: the scene, both outcomes (``impl``: the implementation under test's, the
built-in port's or --impl's; ``oracle``: ACE's), the field-by-field differences, the seed that
found it, the versions of the port and of ACE, which implementation answered on the port's side
(an `ImplementationRun`: the --impl command, its handshake and its stderr when it failed; absent
for the built-in port) and how the scene was shrunk (`Shrink`: against live ACE, against the
built-in port standing in for a recorded ACE, or not, and why). ``acconform.case/2`` files (the
same, with the implementation's outcome under ``port``, a name that elsewhere means the built-in
port) and ``acconform.case/1`` files (``port`` too; no implementation, no shrink label) are still
read. ``acconform.record/1``: one scene with the outcome ACE gave, its version and runtime -- data
only, ACE's answers, never its code.
`load_document` reads any acconform JSON file and dispatches on its "format".
"""

from __future__ import annotations

import re
from dataclasses import dataclass, field
from pathlib import Path

from .codec import Reader, dumps, dumps_compact, json_line, parse_json_text
from .compare import MODES
from .errors import InvalidScene
from .outcome import (FORMAT as OUTCOME_FORMAT, FORMAT_V1 as OUTCOME_FORMAT_V1, FORMAT_V2 as OUTCOME_FORMAT_V2,
                      FORMAT_V3 as OUTCOME_FORMAT_V3, FORMAT_V4 as OUTCOME_FORMAT_V4, FORMAT_V5 as OUTCOME_FORMAT_V5, Outcome)
from .scene import (FORMAT as SCENE_FORMAT, FORMAT_V1 as SCENE_FORMAT_V1, FORMAT_V2 as SCENE_FORMAT_V2,
                    FORMAT_V3 as SCENE_FORMAT_V3, FORMAT_V4 as SCENE_FORMAT_V4, FORMAT_V5 as SCENE_FORMAT_V5,
                    FORMAT_V6 as SCENE_FORMAT_V6, FORMAT_V7 as SCENE_FORMAT_V7, Scene, check_format)

CASE_FORMAT = "acconform.case/3"
CASE_FORMAT_V2 = "acconform.case/2"  # read, never written: the implementation's outcome under "port"
CASE_FORMAT_V1 = "acconform.case/1"
RECORD_FORMAT = "acconform.record/1"


@dataclass(frozen=True, slots=True)
class Versions:
    acconform: str = ""
    ace: str = ""  # ACE commit or assembly version the oracle ran
    runtime: str = ""  # e.g. "mono 6.8.0.105" or "coreclr 10.0.0"

    def to_json(self):
        return {"acconform": self.acconform, "ace": self.ace, "runtime": self.runtime}

    @staticmethod
    def from_json(r: Reader) -> "Versions":
        r.obj({"acconform", "ace", "runtime"})
        v = Versions(*(r[k].str_() if r.given(k) else "" for k in ("acconform", "ace", "runtime")))
        # the runtime decides whose arithmetic a replay computes with (numerics.runtime_named): a
        # runtime it cannot name is refused here, not met as an error when the case is replayed
        from .numerics import RUNTIMES

        if v.runtime.strip() and not {part.split()[0] for part in v.runtime.split(";") if part.strip()} <= set(RUNTIMES):
            r["runtime"].fail(f"unknown runtime {v.runtime!r}: it starts with one of {', '.join(sorted(RUNTIMES))} "
                              "(e.g. \"mono 6.8.0.105\"), or is empty when not recorded")
        return v


# How much of an implementation's stderr a case keeps: all of it up to this many characters; past
# it the first STDERR_HEAD and the last (STDERR_LIMIT - STDERR_HEAD), with a line saying how much
# was left out between (the banner at the top and the error at the bottom both survive).
STDERR_LIMIT = 64 * 1024
STDERR_HEAD = 8 * 1024


def bound_stderr(text: str) -> str:
    if len(text) <= STDERR_LIMIT:
        return text
    tail = STDERR_LIMIT - STDERR_HEAD
    left_out = len(text) - STDERR_LIMIT
    return f"{text[:STDERR_HEAD]}\n[... {left_out} characters left out (cases keep {STDERR_LIMIT}) ...]\n{text[-tail:]}"


@dataclass(frozen=True, slots=True)
class ImplementationRun:
    """The implementation under test that answered a case (--impl): what `repro` starts again."""

    command: str
    cwd: str = ""  # the directory it was started in (a relative command is relative to it)
    handshake: dict = field(default_factory=dict)  # as the implementation sent it (checked)
    stderr: str = ""  # its stderr when it failed on this scene (crash, hang, bad answer), bounded

    def to_json(self):
        d = {"command": self.command, "cwd": self.cwd, "handshake": self.handshake}
        if self.stderr:
            d["stderr"] = self.stderr
        return d

    @staticmethod
    def from_json(r: Reader) -> "ImplementationRun":
        r.obj({"command", "cwd", "handshake", "stderr"})
        hello = r["handshake"].value if r.has("handshake") else {}
        if not isinstance(hello, dict):
            r["handshake"].fail("expected an object (the implementation's handshake)")
        command = r["command"].str_()
        if not command.strip():
            r["command"].fail("empty: the command that started the implementation")
        return ImplementationRun(command, r["cwd"].str_() if r.has("cwd") else "", hello,
                                 r["stderr"].str_() if r.has("stderr") else "")


SHRUNK_AGAINST = ("ace", "port", "none")


@dataclass(frozen=True, slots=True)
class Shrink:
    """How a case's scene was shrunk: against live ACE, against the built-in port standing in for
    a recorded ACE (it agreed with ACE's recorded answer on the original scene), or not at all."""

    against: str = "none"  # one of SHRUNK_AGAINST
    note: str = ""  # why not, or what it took
    bytes_before: int = 0  # the scene's JSON, before and after (0: not measured)
    bytes_after: int = 0

    def to_json(self):
        return {"against": self.against, "note": self.note, "bytes_before": self.bytes_before,
                "bytes_after": self.bytes_after}

    @staticmethod
    def from_json(r: Reader) -> "Shrink":
        r.obj({"against", "note", "bytes_before", "bytes_after"})
        against = r["against"].str_()
        if against not in SHRUNK_AGAINST:
            r["against"].fail(f"expected one of {', '.join(SHRUNK_AGAINST)}, got {against!r}")
        sizes = []
        for k in ("bytes_before", "bytes_after"):
            v = r[k].value if r.has(k) else 0
            if isinstance(v, bool) or not isinstance(v, int) or v < 0:
                r[k].fail(f"expected a byte count, got {v!r}")
            sizes.append(v)
        return Shrink(against, r["note"].str_() if r.has("note") else "", *sizes)


@dataclass(frozen=True, slots=True)
class Case:
    scene: Scene
    port: Outcome  # the implementation under test's outcome ("impl" in the file; "port" before case/3)
    oracle: Outcome
    differences: tuple[str, ...] = ()  # human-readable "field: port=... oracle=..." lines (impl=... for --impl)
    seed: str = ""
    mode: str = "exact"
    versions: Versions = field(default_factory=Versions)
    implementation: ImplementationRun | None = None  # None: the built-in port (or a case/1 file, which does not say)
    shrink: Shrink = field(default_factory=Shrink)
    format: str = CASE_FORMAT  # as read (a case/1 file names no implementation)

    def to_json(self):
        d = {"format": CASE_FORMAT, "seed": self.seed, "mode": self.mode, "versions": self.versions.to_json()}
        if self.implementation is not None:
            d["implementation"] = self.implementation.to_json()
        d["shrunk"] = self.shrink.to_json()
        d.update({"differences": list(self.differences), "scene": self.scene.to_json(),
                  "impl": self.port.to_json(), "oracle": self.oracle.to_json()})
        return d

    @staticmethod
    def from_json(doc, path: str = "") -> "Case":
        r = Reader(doc, path)
        fmt = doc.get("format") if isinstance(doc, dict) else None
        v1 = fmt == CASE_FORMAT_V1
        tested = "port" if fmt in (CASE_FORMAT_V1, CASE_FORMAT_V2) else "impl"  # the key of the tested side's outcome
        r.obj({"format", "seed", "mode", "versions", "differences", "scene", tested, "oracle",
               *(() if v1 else ("implementation", "shrunk"))})
        if not v1:
            check_format(r, CASE_FORMAT_V2 if fmt == CASE_FORMAT_V2 else CASE_FORMAT)
        return Case(
            scene=Scene.from_json(r["scene"].value, r["scene"].path),
            port=Outcome.from_json(r[tested].value, r[tested].path),
            oracle=Outcome.from_json(r["oracle"].value, r["oracle"].path),
            differences=tuple(d.str_() for d in r["differences"].list()) if r.given("differences") else (),
            seed=_seed(r["seed"]) if r.given("seed") else "",
            mode=_mode(r["mode"]) if r.given("mode") else "exact",
            versions=Versions.from_json(r["versions"]) if r.given("versions") else Versions(),
            implementation=ImplementationRun.from_json(r["implementation"]) if r.given("implementation") else None,
            shrink=Shrink.from_json(r["shrunk"]) if r.given("shrunk") else Shrink(),
            format=fmt if fmt in (CASE_FORMAT_V1, CASE_FORMAT_V2) else CASE_FORMAT,
        )


def _seed(r: Reader) -> str:
    """A case's seed: the campaign seed that drew its scene, a whole number written as a string
    (`check --seed`), or "" when none did."""
    seed = r.str_()
    if seed and not re.fullmatch(r"-?[0-9]+", seed):
        r.fail(f"expected a whole number written as a string (the campaign's --seed), or \"\", got {seed!r}")
    return seed


def _mode(r: Reader) -> str:
    mode = r.str_()
    if mode not in MODES:
        r.fail(f"expected one of {', '.join(MODES)}, got {mode!r}")
    return mode


@dataclass(frozen=True, slots=True)
class Record:
    scene: Scene
    outcome: Outcome
    versions: Versions = field(default_factory=Versions)

    def to_json(self):
        return {"format": RECORD_FORMAT, "versions": self.versions.to_json(),
                "scene": self.scene.to_json(), "outcome": self.outcome.to_json()}

    @staticmethod
    def from_json(doc, path: str = "") -> "Record":
        r = Reader(doc, path)
        r.obj({"format", "versions", "scene", "outcome"})
        check_format(r, RECORD_FORMAT)
        return Record(Scene.from_json(r["scene"].value, r["scene"].path),
                      Outcome.from_json(r["outcome"].value, r["outcome"].path),
                      Versions.from_json(r["versions"]) if r.given("versions") else Versions())


_READERS = {SCENE_FORMAT_V1: Scene.from_json, SCENE_FORMAT_V2: Scene.from_json, SCENE_FORMAT_V3: Scene.from_json,
            SCENE_FORMAT_V4: Scene.from_json, SCENE_FORMAT_V5: Scene.from_json, SCENE_FORMAT_V6: Scene.from_json,
            SCENE_FORMAT_V7: Scene.from_json, SCENE_FORMAT: Scene.from_json,
            OUTCOME_FORMAT_V1: Outcome.from_json, OUTCOME_FORMAT_V2: Outcome.from_json, OUTCOME_FORMAT_V3: Outcome.from_json,
            OUTCOME_FORMAT_V4: Outcome.from_json, OUTCOME_FORMAT_V5: Outcome.from_json, OUTCOME_FORMAT: Outcome.from_json,
            CASE_FORMAT_V1: Case.from_json, CASE_FORMAT_V2: Case.from_json, CASE_FORMAT: Case.from_json, RECORD_FORMAT: Record.from_json}


def parse_document(doc, source: str | None = None):
    """A Scene, Outcome, Case or Record from parsed JSON, by its "format" field."""
    try:
        if not isinstance(doc, dict):
            raise InvalidScene("", "expected a JSON object with a \"format\" field")
        fmt = doc.get("format")
        if not isinstance(fmt, str):
            raise InvalidScene("format", "missing required field (e.g. \"acconform.scene/1\")")
        reader = _READERS.get(fmt)
        if reader is None:
            family, _, version = fmt.partition("/")
            known = {f.partition("/")[0]: f for f in _READERS}
            if family in known:
                raise InvalidScene("format", f"unknown format version {version!r} (this acconform reads {known[family]})")
            raise InvalidScene("format", f"unknown format {fmt!r} (known: {', '.join(sorted(_READERS))})")
        from . import deep

        return deep.retrying(reader, doc)  # a BSP thousands of levels deep reads on a deep stack
    except InvalidScene as e:
        raise e.in_file(source) if source and not e.source else e


def load_document(path: str | Path):
    path = Path(path)
    try:
        text = path.read_text(encoding="utf-8")
    except FileNotFoundError:
        raise InvalidScene("", "no such file", str(path)) from None
    except (OSError, UnicodeDecodeError) as e:
        raise InvalidScene("", f"cannot read: {e}", str(path)) from None
    return parse_document(parse_json_text(text, str(path)), str(path))


def is_lines_file(path: str | Path) -> bool:
    """A JSON-lines file (a corpus shard, ``.jsonl.gz``, or plain ``.jsonl``): one document per line."""
    return str(path).endswith((".jsonl.gz", ".jsonl"))


def jsonl_lines(path: str | Path):
    """(line number, line) for each non-empty line of a JSON-lines file, gzip'd when it ends in .gz.

    InvalidScene names the file and the last line read when it is missing, truncated or corrupt,
    and names a file that holds no document (a 0-byte shard reads as an empty gzip stream).
    """
    import gzip
    import zlib

    path = Path(path)
    lineno = 0
    documents = False
    try:
        opener = gzip.open if path.name.endswith(".gz") else open
        with opener(path, "rt", encoding="utf-8") as f:
            for lineno, line in enumerate(f, 1):
                if not line.isspace():  # (not strip(): that copies every line, a third of loading a corpus)
                    documents = True
                    yield lineno, line
    except FileNotFoundError:
        raise InvalidScene("", "no such file", str(path)) from None
    except (OSError, EOFError, zlib.error, UnicodeDecodeError) as e:
        why = "truncated" if isinstance(e, EOFError) else f"corrupt ({e})"
        raise InvalidScene("", f"{why} after line {lineno}; the rest cannot be read", str(path)) from None
    if not documents:
        raise InvalidScene("", f"empty: no document in it ({path.stat().st_size} bytes)", str(path))


def iter_documents(path: str | Path):
    """(where, document) for each document in `path`: one for a JSON file, one per line for a
    JSON-lines shard (where = "FILE line N"). A bad line raises InvalidScene naming it."""
    if not is_lines_file(path):
        yield str(path), load_document(path)
        return
    for lineno, line in jsonl_lines(path):
        where = f"{path} line {lineno}"
        yield where, parse_document(json_line(line, where), where)


def write_document(path: str | Path, doc) -> Path:
    """Write a record's JSON atomically (temp file then rename): a crash never leaves half a file."""
    path = Path(path)
    path.parent.mkdir(parents=True, exist_ok=True)
    from . import deep

    try:
        text = dumps(doc.to_json())
    except RecursionError:  # a BSP thousands of levels deep: written on a deep stack, without the
        # indentation (Python's indenting writer is a generator per level: quadratic in the depth)
        text = deep.call(lambda: dumps_compact(doc.to_json()))
    tmp = path.with_name(path.name + ".tmp")
    tmp.write_text(text + "\n", encoding="utf-8")
    tmp.replace(path)
    return path
