"""Deeply nested documents: a scene whose BSP is thousands of levels deep is read, written and run.

ACE reads and walks a BSP recursively (BSPNode.ReadNode, sphere_intersects_poly, ...), and so do
the port (which follows ACE's decomposition) and the JSON readers. Python's default recursion limit
(1,000) stops them near 1,000 levels, where ACE goes on. `retrying(fn, ...)` calls `fn` as it is
(the fast path every ordinary scene takes) and, only when that raises RecursionError, calls it
again in a thread with a large stack and a raised recursion limit. A document nested deeper than
MAX_DEPTH levels (`loads` counts them exactly) is refused with one line (`TooDeep`, exit 2), never
a traceback.
"""

from __future__ import annotations

import json
import sys
import threading

from .errors import InvalidScene

# how deeply a document may nest (JSON levels; a BSP node is one level): reading and writing one
# take a Python frame per level, so the deep call that reads has this recursion limit (and a
# little for the frames below it). ACE on mono runs a BSP 19,900 levels deep (measured on the
# oracle's main thread, whose stack is 8 MB).
MAX_DEPTH = 20_000
READ_FRAMES = MAX_DEPTH + 200
# the port's recursive BSP queries take up to a few frames per level (a query and the child it
# asks): a scene that reads runs within this limit
RUN_FRAMES = 5 * MAX_DEPTH
# the deep thread's stack: the C JSON reader and writer use ~0.2-0.5 KB per level; only the pages
# touched are ever committed
STACK_BYTES = 512 << 20

_lock = threading.Lock()  # threading.stack_size and the recursion limit are process-wide


class TooDeep(InvalidScene):
    """Nested deeper than MAX_DEPTH levels."""

    def __init__(self, source: str | None = None):
        super().__init__("", f"nested more than {MAX_DEPTH:,} levels deep (a BSP or JSON value); "
                             f"acconform reads and runs at most {MAX_DEPTH:,}", source)

    def in_file(self, source: str) -> "TooDeep":
        return TooDeep(source)


def call(fn, *args, frames: int = READ_FRAMES, **kwargs):
    """`fn(*args, **kwargs)` in a thread with a STACK_BYTES stack and a recursion limit of `frames`;
    its exception is raised here, a RecursionError as TooDeep."""
    box: dict = {}

    def body():
        try:
            box["value"] = fn(*args, **kwargs)
        except RecursionError:
            box["error"] = TooDeep()
        except BaseException as e:  # noqa: BLE001 - handed to the caller's thread
            box["error"] = e

    with _lock:
        old_limit = sys.getrecursionlimit()
        old_stack = threading.stack_size(STACK_BYTES)
        try:
            sys.setrecursionlimit(max(old_limit, frames))
            thread = threading.Thread(target=body, name="acconform-deep", daemon=True)
            thread.start()
        finally:
            threading.stack_size(old_stack)
        try:
            thread.join()
        finally:
            sys.setrecursionlimit(old_limit)
    if "error" in box:
        raise box["error"]
    return box["value"]


def retrying(fn, *args, **kwargs):
    """`fn(*args, **kwargs)`; if it runs out of recursion depth, again with a deep stack (`call`)."""
    try:
        return fn(*args, **kwargs)
    except RecursionError:
        pass  # outside the handler: the traceback of the shallow attempt is not kept alive
    return call(fn, *args, **kwargs)


def loads(text: str):
    """JSON text parsed (json.loads, on a deep stack when it nests deeply); TooDeep when it nests
    more than MAX_DEPTH levels (``[[]]`` is 2), counted exactly: the deep stack's frame limit alone
    lets a few hundred more through. ValueError when it is not JSON."""
    value = retrying(json.loads, text)
    # a text holding no more than MAX_DEPTH brackets cannot nest deeper: most are measured by a count
    if text.count("[") + text.count("{") > MAX_DEPTH and nesting(value) > MAX_DEPTH:
        raise TooDeep()
    return value


def nesting(value) -> int:
    """How many levels a parsed JSON value nests: 0 for a number or string, 1 for ``[]`` or ``{}``,
    one more for each container inside (walked with a list, not recursion: it may be 20,000 deep)."""
    deepest = 0
    todo = [(value, 1)]
    while todo:
        v, level = todo.pop()
        children = v.values() if isinstance(v, dict) else v if isinstance(v, list) else None
        if children is None:
            continue
        deepest = max(deepest, level)
        todo.extend((c, level + 1) for c in children if isinstance(c, (dict, list)))
    return deepest
