"""Pictures of a difference: one self-contained HTML page per case, and an index of a failures directory.

`explain_page(case, explanation, name)` draws the case's scene from above and from the side (SVG,
world metres): the terrain's triangles (as the port builds them), the outdoor cell grid and the
landblock borders, the EnvCells' polygons, the static objects (BSP polygons, spheres, cylinders),
the mover's sphere at the begin, at every step and at the end of each side's run (the reference in
blue, the implementation in orange), the requested end, the contact planes (green) and collision
normals (red) the steps met, and the first divergence marked where it falls (its record's position;
before the steps, at the begin). The page opens with the outcome's differing fields and both values;
then the first divergence in words, the views (framed on the mover's path and the statics it came
near, never a thin strip), and the trace table, open at the first divergence with the records around
it, the rest folded. It reads from 1,000 to 1,600 px wide. `report_page(entries)` indexes the cases of a failures directory by
their first divergence. Nothing is fetched: no script, style sheet or font from elsewhere.
"""

from __future__ import annotations

import html
import math
from pathlib import Path

from .errors import AcconformError

BLOCK = 192.0
CELL = 24.0
MARGIN = 4.0  # metres around what the run touched
VIEW = 620  # pixels, the longer side of a view
ASPECT = 0.55  # a view's shorter side is at least this share of its longer one: never a thin strip
AROUND = 12  # trace records shown open around the first divergence, on each side
FOLDED = 1500  # records at most in each folded part of the trace table (before and after)
REF, IMPL = "#1f6fd1", "#e07b00"


def check_writable(path: str) -> None:
    """Bad output path: one line (exit 2) before anything runs."""
    p = Path(path)
    if p.is_dir():
        raise AcconformError(f"--html {path}: is a directory; give a file name (e.g. {p / 'case.html'})")
    if not p.parent.exists():
        raise AcconformError(f"--html {path}: directory {p.parent} does not exist")


def write_page(path: str, text: str) -> Path:
    p = Path(path)
    try:
        p.write_text(text, encoding="utf-8")
    except OSError as e:
        raise AcconformError(f"--html {path}: cannot write it ({e.strerror or e})") from None
    return p


def _glob(cell: int, origin) -> tuple[float, float, float]:
    """A landblock-relative position as world metres (x east, y north, z up)."""
    return ((cell >> 24) * BLOCK + origin[0], ((cell >> 16) & 0xFF) * BLOCK + origin[1], origin[2])


def _rotate(q, v):
    w, x, y, z = q
    # v + 2 w (u x v) + 2 u x (u x v), u = (x, y, z)
    cx, cy, cz = y * v[2] - z * v[1], z * v[0] - x * v[2], x * v[1] - y * v[0]
    ccx, ccy, ccz = y * cz - z * cy, z * cx - x * cz, x * cy - y * cx
    return (v[0] + 2 * (w * cx + ccx), v[1] + 2 * (w * cy + ccy), v[2] + 2 * (w * cz + ccz))


def _terrain(scene) -> list[tuple[tuple, ...]]:
    """The terrain triangles in world metres, built by the port as both sides build them."""
    from .numerics import get_mode
    from .port.run import scene_world

    lscape = scene_world(scene, get_mode("exact", "coreclr"))[0]
    tris = []
    try:
        for lb in scene.landblocks:
            if not lb.has_terrain:
                continue
            block = lscape.get_landblock(lb.id)
            # cell by cell (each built as it is read: a landblock makes a cell's polygons with it)
            polygons = [p for key, cell in block.land_cells.items() if key < 0x100 for p in cell.polygons]
            for poly in polygons:
                pts = [v.origin for v in poly.vertices if v is not None]
                if len(pts) == 3:
                    tris.append(tuple(_glob(lb.id, (float(p.x), float(p.y), float(p.z))) for p in pts))
    finally:
        lscape.release()
    return tris


def _shape_polygons(obj) -> list[tuple[tuple, ...]]:
    shape = obj.shape
    if getattr(shape, "kind", "") != "bsp":
        return []
    out = []
    for poly in shape.polygons:
        out.append(tuple(_glob(obj.position.cell, tuple(
            o + r * obj.scale for o, r in zip(obj.position.frame.origin, _rotate(obj.position.frame.orientation, v))))
            for v in poly.vertices))
    return out


def _env_polygons(scene) -> list[tuple[tuple, ...]]:
    envs = {e.id: e for e in scene.environments}
    out = []
    for cell in scene.env_cells:
        env = envs.get(cell.environment)
        if env is None or cell.cell_structure >= len(env.cell_structs):
            continue
        for poly in env.cell_structs[cell.cell_structure].polygons:
            out.append(tuple(_glob(cell.id, tuple(o + r for o, r in zip(cell.frame.origin, _rotate(cell.frame.orientation, v))))
                             for v in poly.vertices))
    return out


class _View:
    """A projection of world metres to SVG pixels: top (x, y) or side (x or y, z)."""

    def __init__(self, axes: tuple[int, int], lo: tuple[float, float], hi: tuple[float, float]):
        self.axes = axes
        self.lo = lo
        span = max(hi[0] - lo[0], hi[1] - lo[1], 1.0)
        self.scale = VIEW / span
        self.w = int((hi[0] - lo[0]) * self.scale) + 1
        self.h = int((hi[1] - lo[1]) * self.scale) + 1

    def xy(self, p) -> tuple[float, float]:
        a, b = self.axes
        return (round((p[a] - self.lo[0]) * self.scale, 2), round(self.h - (p[b] - self.lo[1]) * self.scale, 2))

    def inside(self, pts) -> bool:
        return any(-self.w * 0.5 <= x <= self.w * 1.5 and -self.h * 0.5 <= y <= self.h * 1.5
                   for x, y in map(self.xy, pts))


def _svg(view: _View, title: str, layers: list[str]) -> str:
    return (f'<figure><svg xmlns="http://www.w3.org/2000/svg" class="view" data-view="{title}" width="{view.w}" '
            f'height="{view.h}" viewBox="0 0 {view.w} {view.h}"><rect width="100%" height="100%" fill="#fbfaf6"/>'
            + "".join(layers) + f'</svg><figcaption>{title}</figcaption></figure>')


def _poly(view, pts, cls, fill="none", stroke="#999", width=0.6):
    d = " ".join(f"{x},{y}" for x, y in map(view.xy, pts))
    return f'<polygon class="{cls}" points="{d}" fill="{fill}" stroke="{stroke}" stroke-width="{width}"/>'


def _circle(view, c, r, cls, stroke, fill="none", width=1.2, title=""):
    x, y = view.xy(c)
    t = f"<title>{html.escape(title)}</title>" if title else ""
    return (f'<circle class="{cls}" cx="{x}" cy="{y}" r="{max(r * view.scale, 1.5):.2f}" fill="{fill}" '
            f'stroke="{stroke}" stroke-width="{width}">{t}</circle>')


def _arrow(view, c, v, cls, color, length=1.0):
    x1, y1 = view.xy(c)
    x2, y2 = view.xy(tuple(a + b * length for a, b in zip(c, v)))
    return f'<line class="{cls}" x1="{x1}" y1="{y1}" x2="{x2}" y2="{y2}" stroke="{color}" stroke-width="1.6"/>'


def _path_points(records, scene):
    """(label, world centre of the mover's first sphere, record) at each step record (or tick)."""
    s = scene.mover.spheres[0] if scene.mover.spheres else None
    lift = s.center[2] * scene.mover.scale if s is not None else 0.0
    out = []
    for r in records:
        if r.event == "step" and r.path is not None:
            c = _glob(r.path.check_cell or scene.mover.begin.cell, r.path.check_pos)
            out.append((f"step {r.step}", (c[0], c[1], c[2] + lift), r))
        elif r.event == "tick" and r.mover is not None:
            c = _glob(r.mover.cell, r.mover.origin)
            out.append((f"tick {r.tick}", (c[0], c[1], c[2] + lift), r))
    return out


def _end_point(outcome, scene):
    if outcome is None or outcome.error is not None:
        return None
    s = scene.mover.spheres[0] if scene.mover.spheres else None
    lift = s.center[2] * scene.mover.scale if s is not None else 0.0
    if outcome.ticks:
        t = outcome.ticks[-1]
        c = _glob(t.cell, t.origin)
    else:
        c = _glob(outcome.cell or scene.mover.begin.cell, outcome.origin)
    return (c[0], c[1], c[2] + lift)


def _framed(lo, hi):
    """(lo, hi) widened about their centre so the shorter side is at least ASPECT of the longer."""
    span = [hi[0] - lo[0], hi[1] - lo[1]]
    want = max(span) * ASPECT
    lo, hi = list(lo), list(hi)
    for i in (0, 1):
        if span[i] < want:
            grow = (want - span[i]) / 2
            lo[i] -= grow
            hi[i] += grow
    return tuple(lo), tuple(hi)


def _touched(path, radius, statics) -> list[tuple]:
    """Points of the static objects the mover came near (within MARGIN of its sphere on the path):
    the view holds what the mover touched, not only where it went."""
    lo = [min(p[i] for p in path) - radius - MARGIN for i in range(3)]
    hi = [max(p[i] for p in path) + radius + MARGIN for i in range(3)]
    out = []
    for obj, polys in statics:
        at = _glob(obj.position.cell, obj.position.frame.origin)
        pts = [v for poly in polys for v in poly] or [at]
        if any(all(lo[i] <= v[i] <= hi[i] for i in range(3)) for v in pts):
            out.extend(v for v in pts if all(abs(v[i] - (lo[i] + hi[i]) / 2) < 4 * (hi[i] - lo[i]) for i in range(3)))
    return out


def _divergence_point(e, scene, ours, begin, lift) -> tuple[tuple, str]:
    """Where to mark the first divergence, and in words: at the diverging record's own position (its
    transition's check position, or the mover after a tick) when it has one; at the static being placed
    when they part placing an outdoor static; else at the last step before it; else, before the steps, at the begin."""
    d = e.divergence
    r = d.a if d.a is not None else d.b
    if r is not None and r.path is not None and (r.path.check_cell or r.step is not None):
        c = _glob(r.path.check_cell or scene.mover.begin.cell, r.path.check_pos)
        return (c[0], c[1], c[2] + lift), f"record {d.a_position}: the transition's check position"
    if r is not None and r.mover is not None:
        c = _glob(r.mover.cell, r.mover.origin)
        return (c[0], c[1], c[2] + lift), f"record {d.a_position}: the mover"
    placed = next((o for o in scene.objects if r is not None and r.placing and o.id == r.placing), None)
    if placed is not None:  # the world's static being placed where they part
        c = _glob(placed.position.cell, placed.position.frame.origin)
        return (c[0], c[1], c[2] + lift), f"record {d.a_position}: placing static {placed.id:#x}"
    index = {id(x): i for i, x in enumerate(e.ours)}
    before = [(label, c) for label, c, x in ours if index.get(id(x), len(e.ours)) <= d.a_position]
    if before:
        return before[-1][1], f"in {before[-1][0]}"
    return begin, "before the steps: at the begin"


def _views(case, e) -> list[str]:
    scene = case.scene
    m = scene.mover
    radius = (m.spheres[0].radius if m.spheres else 0.5) * m.scale
    lift = (m.spheres[0].center[2] if m.spheres else 0.0) * m.scale
    begin = _glob(m.begin.cell, m.begin.frame.origin)
    begin = (begin[0], begin[1], begin[2] + lift)
    end = _glob(m.end.cell, m.end.frame.origin) if m.end is not None else None
    end = (end[0], end[1], end[2] + lift) if end is not None else None
    ours = _path_points(e.ours, scene)
    theirs = _path_points(e.theirs, scene)
    our_end, their_end = _end_point(case.oracle, scene), _end_point(e.implementation_outcome, scene)
    # framed on where the mover went (the requested end is drawn when it falls inside, never framed on: a
    # mover stopped a metre out would otherwise be a dot in a corner of a view of the whole request)
    path = [begin] + [p for _, p, _ in ours + theirs] + [p for p in (our_end, their_end) if p is not None]
    path = [p for p in path if all(math.isfinite(x) and abs(x) < 1e6 for x in p)] or [begin]
    statics = [(o, _shape_polygons(o)) for o in scene.objects]
    pts = path + _touched(path, radius, statics)
    lo = [min(p[i] for p in pts) - MARGIN - radius for i in range(3)]
    hi = [max(p[i] for p in pts) + MARGIN + radius for i in range(3)]
    side_axis = 0 if hi[0] - lo[0] >= hi[1] - lo[1] else 1
    top = _View((0, 1), *_framed((lo[0], lo[1]), (hi[0], hi[1])))
    side = _View((side_axis, 2), *_framed((lo[side_axis], lo[2] - 2.0), (hi[side_axis], hi[2] + 2.0)))
    terrain = _terrain(scene)
    env = _env_polygons(scene)
    d = e.divergence
    marked = _divergence_point(e, scene, ours, begin, lift) if d is not None else None
    figures = []
    for view, name in ((top, "top view (x east, y north)"), (side, f"side view ({'xy'[side_axis]} across, z up)")):
        layers = ['<g class="terrain">']
        for tri in terrain:
            if view.inside(tri):
                layers.append(_poly(view, tri, "terrain", fill="#eef2e4", stroke="#b9c2a4", width=0.5))
        layers.append("</g><g class=\"cells\">")
        if view.axes == (0, 1):
            for gx in range(int(lo[0] // CELL), int(hi[0] // CELL) + 2):
                x, _ = view.xy((gx * CELL, 0, 0))
                layers.append(f'<line class="cell-border" x1="{x}" y1="0" x2="{x}" y2="{view.h}" stroke='
                              f'"{"#7a6a3a" if gx * CELL % BLOCK == 0 else "#d8cfb0"}" stroke-width="0.8"/>')
            for gy in range(int(lo[1] // CELL), int(hi[1] // CELL) + 2):
                _, y = view.xy((0, gy * CELL, 0))
                layers.append(f'<line class="cell-border" x1="0" y1="{y}" x2="{view.w}" y2="{y}" stroke='
                              f'"{"#7a6a3a" if gy * CELL % BLOCK == 0 else "#d8cfb0"}" stroke-width="0.8"/>')
        for poly in env:
            if view.inside(poly):
                layers.append(_poly(view, poly, "env-cell", fill="#f2ecf7", stroke="#9b7cb6"))
        layers.append("</g><g class=\"objects\">")
        for obj, polys in statics:
            for poly in polys:
                if view.inside(poly):
                    layers.append(_poly(view, poly, "object", fill="#e3e3e3", stroke="#555", width=0.8))
            shape = obj.shape
            at = _glob(obj.position.cell, obj.position.frame.origin)
            if getattr(shape, "kind", "") == "sphere":
                c = tuple(a + b * obj.scale for a, b in zip(at, shape.sphere.center))
                layers.append(_circle(view, c, shape.sphere.radius * obj.scale, "object", "#555", "#e3e3e3"))
            elif getattr(shape, "kind", "") == "cylsphere":
                c = tuple(a + b * obj.scale for a, b in zip(at, shape.low_point))
                layers.append(_circle(view, c, shape.radius * obj.scale, "object", "#555", "#e3e3e3"))
        layers.append("</g><g class=\"mover\">")
        layers.append(_circle(view, begin, radius, "sphere begin", "#333", width=1.6, title="begin"))
        if end is not None:  # outside the view: at its edge, in the direction of the requested end
            x, y = view.xy(end)
            off = not (0 <= x <= view.w and 0 <= y <= view.h)
            x, y = min(max(x, 7), view.w - 7), min(max(y, 7), view.h - 7)
            title = "requested end" + (", outside the view in this direction" if off else "")
            layers.append(f'<g class="requested-end"><title>{title}</title><line x1="{x - 6}" y1="{y - 6}" '
                          f'x2="{x + 6}" y2="{y + 6}" stroke="#333" stroke-width="1.5"/><line x1="{x - 6}" y1="{y + 6}" '
                          f'x2="{x + 6}" y2="{y - 6}" stroke="#333" stroke-width="1.5"/></g>')
        for points, color, side_name in ((ours, REF, "reference"), (theirs, IMPL, "implementation")):
            for label, c, r in points:
                layers.append(_circle(view, c, radius, f"sphere step {side_name}", color, width=0.9,
                                      title=f"{side_name} {label}"))
                p = r.path
                if p is not None and p.contact_plane.valid:
                    layers.append(_arrow(view, c, p.contact_plane.normal, "contact-plane", "#2e9d4b"))
                if p is not None and p.collision_normal.valid:
                    layers.append(_arrow(view, c, p.collision_normal.vector, "collision-normal", "#d11f1f"))
        for c, color, side_name in ((our_end, REF, "reference"), (their_end, IMPL, "implementation")):
            if c is not None:
                layers.append(_circle(view, c, radius, f"sphere end {side_name}", color, width=2.2,
                                      title=f"{side_name} end"))
        if marked is not None:
            at, where = marked
            x, y = view.xy(at)
            layers.append(f'<g class="divergence" data-where="{html.escape(where)}"><title>first divergence: '
                          f'{html.escape(d.key())} ({html.escape(where)})</title>'
                          f'<circle cx="{x}" cy="{y}" r="{max(radius * view.scale, 4) + 6:.1f}" fill="none" '
                          f'stroke="#d11f1f" stroke-width="2.5" stroke-dasharray="5 3"/></g>')
        layers.append("</g>")
        figures.append(_svg(view, name, layers))
    return figures


def _cell(v) -> str:
    return html.escape("" if v is None else str(v))


def _point(v) -> str:
    return "(" + ", ".join(f"{x:.7g}" for x in v) + ")"


def _rows(ours, theirs, d, lo: int, hi: int) -> str:
    rows = []
    for i in range(lo, hi):
        a = ours[i] if i < len(ours) else None
        b = theirs[i] if i < len(theirs) else None
        r = a or b
        mark = ' class="divergence"' if d is not None and i == d.index else ""
        pos = [_point(x.path.check_pos) if x is not None and x.path is not None else None for x in (a, b)]
        rows.append(f"<tr{mark}><td>{i}</td><td>{_cell(r.tick)}</td><td>{_cell(r.step)}</td><td>{_cell(r.event)}</td>"
                    f"<td>{_cell(r.anchor)}</td><td>{_cell(a.result if a else None)}</td>"
                    f"<td>{_cell(b.result if b else None)}</td><td>{_cell(pos[0])}</td><td>{_cell(pos[1])}</td></tr>")
    return "".join(rows)


_HEAD = ('<thead><tr><th>#</th><th>tick</th><th>step</th><th>event</th><th>anchor</th>'
         '<th>reference result</th><th>implementation result</th><th>reference check position</th>'
         '<th>implementation check position</th></tr></thead>')


def _folded(ours, theirs, d, lo: int, hi: int, what: str, cls: str) -> str:
    if hi <= lo:
        return ""
    shown = (max(lo, hi - FOLDED), hi) if cls == "before" else (lo, min(hi, lo + FOLDED))
    left = (hi - lo) - (shown[1] - shown[0])
    more = f" ({left} more not shown)" if left else ""
    return (f'<details class="trace-{cls}"><summary>{hi - lo} {what}{more}</summary><div class="scroll">'
            f'<table class="trace">{_HEAD}<tbody>{_rows(ours, theirs, d, *shown)}</tbody></table></div></details>')


def _table(e) -> str:
    """The two traces side by side at the implementation's grain: open at the first divergence with
    AROUND records either side, its row marked; the records before and after folded (<details>)."""
    d = e.divergence
    kinds = {(r.anchor, r.event) for r in e.theirs}
    ours = [r for r in e.ours if (r.anchor, r.event) in kinds] if e.theirs else list(e.ours)
    theirs = list(e.theirs)
    n = max(len(ours), len(theirs))
    at = d.index if d is not None else 0
    lo, hi = max(0, at - AROUND), min(n, at + AROUND + 1)
    return (_folded(ours, theirs, d, 0, lo, "records before these", "before")
            + f'<div class="scroll"><table class="trace trace-open">{_HEAD}<tbody>{_rows(ours, theirs, d, lo, hi)}'
            "</tbody></table></div>"
            + _folded(ours, theirs, d, hi, n, "records after these", "after"))


def _differences(case, e) -> str:
    """The outcome's fields that differ, with both values: the implementation's and ACE's."""
    from .compare import _show, compare

    rows = []
    if e.implementation_outcome is not None:
        for x in compare(e.implementation_outcome, case.oracle, case.mode):
            leaf = x.field.rsplit(".", 1)[-1]
            rows.append((x.field, _show(leaf, x.a), _show(leaf, x.b)))
    if not rows and case.differences:
        return ('<section class="differences"><h2>What differs</h2><ul>'
                + "".join(f"<li>{html.escape(line)}</li>" for line in case.differences) + "</ul></section>")
    if not rows:
        return '<section class="differences"><h2>What differs</h2><p>nothing: every field agrees</p></section>'
    body = "".join(f"<tr><td>{html.escape(f)}</td><td>{html.escape(a)}</td><td>{html.escape(b)}</td></tr>"
                   for f, a, b in rows)
    return (f'<section class="differences"><h2>What differs ({len(rows)} field{"s" if len(rows) != 1 else ""})</h2>'
            f'<table class="differences"><thead><tr><th>field</th><th>{html.escape(e.implementation)}</th>'
            f'<th>ACE (the case\'s oracle outcome)</th></tr></thead><tbody>{body}</tbody></table></section>')


STYLE = """body{font:14px/1.4 system-ui,sans-serif;margin:1.5em auto;padding:0 1.5em;max-width:1600px;color:#222}
h1{font-size:1.3em;overflow-wrap:anywhere}h2{font-size:1.1em;margin:1em 0 .4em}
pre{background:#f4f4f4;padding:.7em;white-space:pre-wrap;overflow-wrap:anywhere}
.views{display:flex;flex-wrap:wrap;gap:1em}figure{margin:0;flex:1 1 460px;max-width:100%}
figure svg{width:100%;height:auto;border:1px solid #ddd}figcaption{color:#555;font-size:.9em}
.scroll{overflow-x:auto}table{border-collapse:collapse;font-size:12px}
td,th{border:1px solid #ddd;padding:2px 5px;text-align:left;overflow-wrap:anywhere;vertical-align:top}
table.trace td:nth-child(-n+5),table.trace th{white-space:nowrap}
table.differences{font-size:13px}table.differences td:first-child{font-weight:bold}
tr.divergence td{background:#ffd9d9;font-weight:bold}.legend span{margin-right:1.2em}
details{margin:.4em 0}summary{cursor:pointer;color:#1f4f8f}
.known{color:#7a4b00;background:#fff3d6;padding:.3em .5em}"""


def explain_page(case, e, name: str) -> str:
    from .explain import render

    lines = render(e)
    known = (f'<p class="known">known: ACE differs from retail here ({html.escape(e.known.name)})</p>'
             if e.known is not None else "")
    legend = (f'<p class="legend"><span style="color:{REF}">&#9679; reference ({html.escape(e.reference_name)})</span>'
              f'<span style="color:{IMPL}">&#9679; {html.escape(e.implementation)}</span>'
              '<span style="color:#2e9d4b">&#8212; contact plane normal</span>'
              '<span style="color:#d11f1f">&#8212; collision normal</span>'
              '<span>&#10005; requested end</span><span style="color:#d11f1f">&#9711; first divergence</span></p>')
    return ("<!DOCTYPE html><html lang=\"en\"><head><meta charset=\"utf-8\"><title>acconform explain: "
            f"{html.escape(name)}</title><style>{STYLE}</style></head><body>"
            f"<h1>acconform explain: {html.escape(name)}</h1>"
            f"<p>scene {html.escape(case.scene.name or '(unnamed)')}; implementation {html.escape(e.implementation)}</p>"
            f"{_differences(case, e)}{known}<h2>First divergence</h2>"
            f"<pre class=\"first-divergence\">{html.escape(chr(10).join(lines))}</pre>{legend}"
            f"<div class=\"views\">{''.join(_views(case, e))}</div><h2>Trace</h2>{_table(e)}</body></html>")


def report_page(title: str, entries: list[tuple[str, str, str, str]]) -> str:
    """An index: (group, case file, page link or "", one-line summary) per case, grouped by first divergence."""
    groups: dict[str, list] = {}
    for group, file, link, line in entries:
        groups.setdefault(group, []).append((file, link, line))
    body = [f"<h1>{html.escape(title)}</h1><p>{len(entries)} case{'s' if len(entries) != 1 else ''}, "
            f"{len(groups)} distinct first divergence{'s' if len(groups) != 1 else ''}</p>"]
    for group, cases in groups.items():
        body.append(f'<section class="group"><h2>{html.escape(group)}</h2><ul>')
        for file, link, line in cases:
            target = f'<a href="{html.escape(link)}">{html.escape(file)}</a>' if link else html.escape(file)
            body.append(f'<li class="case">{target}: {html.escape(line)}</li>')
        body.append("</ul></section>")
    return (f"<!DOCTYPE html><html lang=\"en\"><head><meta charset=\"utf-8\"><title>{html.escape(title)}</title>"
            f"<style>{STYLE}</style></head><body>{''.join(body)}</body></html>")
