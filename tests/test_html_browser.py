"""The explain page (acconform explain CASE --html) and the report index, rendered in a real headless
browser (Debian's chromium; .ci/run installs it): what the browser drew is counted in the DOM it
loaded and in the pixels of its screenshot, not only that a file exists."""

from __future__ import annotations

import os
import re
import shutil
import struct
import subprocess
import sys
import zlib
from pathlib import Path

import numpy as np
import pytest

from acconform.case import ImplementationRun
from acconform.compare import compare
from acconform.explain import explain
from acconform.html import AROUND, IMPL, REF, explain_page, report_page
from acconform.protocol import Implementation
from acconform.runner import make_case

ROOT = Path(__file__).resolve().parents[1]
PLANTED = ROOT / "tests" / "impl" / "planted_impl.py"
BUG = "step_down_two_halves_made_thirds"
CHROMIUM = shutil.which("chromium") or shutil.which("chromium-browser")
sys.path.insert(0, str(ROOT / "tests" / "runner"))

pytestmark = pytest.mark.skipif(CHROMIUM is None, reason="no chromium on PATH (apt-get install -y chromium; .ci/run "
                                "installs it where apt is usable)")


def browser(*args: str, timeout: float = 90) -> subprocess.CompletedProcess:
    return subprocess.run([CHROMIUM, "--headless", "--no-sandbox", "--disable-gpu", "--hide-scrollbars",
                           "--no-first-run", "--disable-dev-shm-usage", *args], capture_output=True, timeout=timeout)


def read_png(path: Path) -> np.ndarray:
    """A PNG's pixels as an (h, w, channels) uint8 array (8-bit RGB or RGBA, as chromium writes them)."""
    data = path.read_bytes()
    assert data[:8] == b"\x89PNG\r\n\x1a\n"
    pos, idat = 8, b""
    while pos < len(data):
        length, kind = struct.unpack(">I4s", data[pos:pos + 8])
        body = data[pos + 8:pos + 8 + length]
        if kind == b"IHDR":
            w, h, depth, color = struct.unpack(">IIBB", body[:10])
        elif kind == b"IDAT":
            idat += body
        pos += 12 + length
    assert depth == 8 and color in (2, 6)
    bpp = 3 if color == 2 else 4
    raw = zlib.decompress(idat)
    stride = w * bpp
    out = np.zeros((h, stride), dtype=np.uint8)
    prev = np.zeros(stride, dtype=np.int32)
    for y in range(h):
        f = raw[y * (stride + 1)]
        line = np.frombuffer(raw, dtype=np.uint8, count=stride, offset=y * (stride + 1) + 1).astype(np.int32)
        if f == 0:
            cur = line
        elif f == 2:
            cur = (line + prev) & 0xFF
        else:  # Sub, Average, Paeth: each byte needs the one decoded bpp before it
            cur = line.copy()
            for x in range(stride):
                a = cur[x - bpp] if x >= bpp else 0
                b = prev[x]
                if f == 1:
                    cur[x] = (cur[x] + a) & 0xFF
                elif f == 3:
                    cur[x] = (cur[x] + ((a + b) >> 1)) & 0xFF
                else:
                    c = prev[x - bpp] if x >= bpp else 0
                    p = a + b - c
                    pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
                    cur[x] = (cur[x] + (a if pa <= pb and pa <= pc else b if pb <= pc else c)) & 0xFF
        out[y] = cur
        prev = cur
    return out.reshape(h, w, bpp)


def pixels_of(img: np.ndarray, color: str, tolerance: int = 40) -> int:
    rgb = np.array([int(color[i:i + 2], 16) for i in (1, 3, 5)])
    return int((np.abs(img[:, :, :3].astype(int) - rgb).sum(axis=2) <= tolerance).sum())


# the planted bugs whose pages are drawn: a step-down case, and issue 43's terrain case (a cliff slide)
PAGES = {BUG: "transitional_insert:step_down_halves", "cliff_slide_sign_flipped": None}


@pytest.fixture(scope="module")
def pages(tmp_path_factory):
    return {bug: _page(tmp_path_factory, bug, branch) for bug, branch in PAGES.items()}


@pytest.fixture(scope="module")
def page(pages):
    return pages[BUG]


def _page(tmp_path_factory, bug, branch):
    from mutants import killing_records

    (rec, got), = killing_records(bug, 1, branch=branch)
    command = f"{sys.executable} {PLANTED} {bug}"
    impl = Implementation(command, timeout=60)
    impl.runtime = "coreclr"
    try:
        case = make_case(rec.scene, got, rec.outcome, compare(got, rec.outcome), 0, "exact", rec.versions,
                         ImplementationRun(command, str(ROOT), impl.hello))
        e = explain(rec.scene, rec.outcome, "ACE's recorded answer", impl, "exact", "coreclr")
    finally:
        impl.close()
    folder = tmp_path_factory.mktemp("pages")
    path = folder / "case.html"
    path.write_text(explain_page(case, e, "case.json"), encoding="utf-8")
    return path, e, case


MEASURE = """<script>
const box = s => { const r = s.getBoundingClientRect(); return Math.round(r.width) + "x" + Math.round(r.height); };
document.body.setAttribute("data-scroll-width", document.documentElement.scrollWidth);
document.body.setAttribute("data-views", [...document.querySelectorAll("svg.view")].map(box).join(" "));
document.body.setAttribute("data-h1", box(document.querySelector("h1")));
const hidden = [...document.querySelectorAll("h1, p, pre")].filter(x => x.scrollWidth > x.clientWidth + 1);
document.body.setAttribute("data-cut", hidden.map(x => x.tagName + "." + x.className).join(" ") || "none");
</script>"""


def laid_out(path: Path, width: int, tmp_path: Path) -> dict:
    """The page as chromium lays it out `width` px wide: the document's scroll width, each view's size."""
    probe = tmp_path / f"probe-{width}.html"
    probe.write_text(path.read_text(encoding="utf-8").replace("</body>", MEASURE + "</body>"), encoding="utf-8")
    dom = browser("--dump-dom", f"--window-size={width},1000", probe.as_uri()).stdout.decode()
    body = re.search(r"<body([^>]*)>", dom).group(1)
    get = lambda name: re.search(f'{name}="([^"]*)"', body).group(1)  # noqa: E731
    views = [tuple(int(x) for x in v.split("x")) for v in get("data-views").split()]
    return {"scroll_width": int(get("data-scroll-width")), "views": views, "cut": get("data-cut"),
            "h1": tuple(int(x) for x in get("data-h1").split("x"))}


def test_the_explain_page_loads_in_chromium_with_both_views_the_spheres_and_the_divergence_marked(page):
    path, e, _ = page
    r = browser("--dump-dom", path.as_uri())
    assert r.returncode == 0, r.stderr.decode()[-500:]
    dom = r.stdout.decode()
    views = re.findall(r'<svg[^>]*class="view"[^>]*data-view="([^"]+)"', dom)
    assert len(views) == 2 and views[0].startswith("top view") and views[1].startswith("side view")
    steps = sum(1 for r in e.ours if r.event == "step")
    for side in ("reference", "implementation"):
        # per view: the begin and end spheres and one per step on each side
        assert dom.count(f'class="sphere step {side}"') == 2 * steps
        assert dom.count(f'class="sphere end {side}"') == 2
    assert dom.count('class="sphere begin"') == 2 and dom.count('class="requested-end"') == 2
    assert dom.count('class="terrain"') > 2 and dom.count('class="divergence"') == 3  # two marks, one table row
    assert dom.count("<tr") > 10 and "Transition.cs:TransitionalInsert" in dom


def test_the_explain_pages_screenshot_shows_both_sides_colours_and_the_red_divergence_mark(page, tmp_path):
    path, _, _ = page
    shot = tmp_path / "page.png"
    r = browser(f"--screenshot={shot}", "--window-size=1300,1000", path.as_uri())
    assert r.returncode == 0 and shot.exists(), r.stderr.decode()[-500:]
    img = read_png(shot)
    assert img.shape[0] == 1000 and img.shape[1] == 1300
    assert pixels_of(img, REF) > 200, "the reference's spheres are not drawn"
    assert pixels_of(img, IMPL) > 200, "the implementation's spheres are not drawn"
    assert pixels_of(img, "#d11f1f") > 50, "the first divergence is not marked"
    assert pixels_of(img, "#eef2e4", 8) > 10_000, "no terrain drawn"
    keep = os.environ.get("ACCONFORM_KEEP_SCREENSHOT")  # docs/explain-page.png was taken so
    if keep:
        shutil.copyfile(shot, keep)


def test_the_report_index_loads_in_chromium_with_its_groups_and_links(page, tmp_path):
    path, _, _ = page
    index = tmp_path / "index.html"
    index.write_text(report_page("failures", [("first divergence: A x", "case-1.json", path.as_uri(), "one"),
                                              ("first divergence: A x", "case-2.json", "", "two"),
                                              ("differs in origin", "case-3.json", "", "three")]))
    dom = browser("--dump-dom", index.as_uri()).stdout.decode()
    assert dom.count('<section class="group">') == 2 and dom.count('<li class="case">') == 3
    assert "3 cases, 2 distinct first divergences" in dom and f'href="{path.as_uri()}"' in dom


def test_the_explain_page_lists_the_differing_fields_with_both_values_before_anything_else(page):
    path, e, case = page
    dom = browser("--dump-dom", path.as_uri()).stdout.decode()
    first = dom.index('class="differences"')
    assert first < dom.index('class="first-divergence"') < dom.index('class="view"') < dom.index('class="trace')
    from acconform.compare import _show

    diffs = compare(e.implementation_outcome, case.oracle)
    assert diffs
    section = dom[first:dom.index("</section>", first)]
    for d in diffs:
        leaf = d.field.rsplit(".", 1)[-1]
        assert f"<td>{d.field}</td><td>{_show(leaf, d.a)}</td><td>{_show(leaf, d.b)}</td>" in section


def test_the_trace_table_opens_at_the_first_divergence_with_the_records_around_it_and_folds_the_rest(page):
    path, e, _ = page
    dom = browser("--dump-dom", path.as_uri()).stdout.decode()
    opened = dom[dom.index('class="trace trace-open"'):]
    opened = opened[:opened.index("</table>")]
    assert 'class="divergence"' in opened and opened.count("<tr") <= 2 * AROUND + 2  # the rows and the header
    assert f"<td>{e.divergence.index}</td>" in opened
    assert dom.count("<details") == 2 and " open" not in re.findall(r"<details[^>]*>", dom)[0]
    assert dom.index('class="trace-before"') < dom.index('class="trace trace-open"') < dom.index('class="trace-after"')


def test_a_divergence_before_the_steps_is_marked_at_the_begin_not_at_the_end_of_the_path(page, tmp_path):
    import dataclasses

    from acconform.trace import Divergence

    path, e, case = page
    k = next(i for i, r in enumerate(e.ours) if r.event == "call" and r.step is None)  # a record before the steps
    r = e.ours[k]
    d = Divergence(0, r, r, "result", 1.0, 2.0, r.within or r.anchor, k, k)
    before = tmp_path / "before.html"
    before.write_text(explain_page(case, dataclasses.replace(e, divergence=d), "case.json"), encoding="utf-8")
    dom = browser("--dump-dom", before.as_uri()).stdout.decode()
    marks = re.findall(r'<g class="divergence" data-where="([^"]*)">.*?<circle cx="([\d.]+)" cy="([\d.]+)"', dom)
    begins = re.findall(r'<circle class="sphere begin" cx="([\d.]+)" cy="([\d.]+)"', dom)
    assert len(marks) == 2 and len(begins) == 2
    for (where, x, y), (bx, by) in zip(marks, begins):
        assert where.startswith("before the steps") and (x, y) == (bx, by)


@pytest.mark.parametrize("bug", sorted(PAGES))
@pytest.mark.parametrize("width", [1000, 1300, 1600])
def test_the_explain_page_reads_from_1000_to_1600_px_with_views_large_enough_to_read(pages, tmp_path, width, bug):
    path, _, _ = pages[bug]
    got = laid_out(path, width, tmp_path)
    assert got["scroll_width"] <= width, f"the page is {got['scroll_width']} px wide in a {width} px window"
    assert got["h1"][0] <= width and got["cut"] == "none", f"text cut off (scrolled inside its box): {got['cut']}"
    assert len(got["views"]) == 2
    for w, h in got["views"]:
        assert w >= 400 and h >= 0.45 * w, f"a view of {w}x{h} px: a thin strip ({got['views']})"


@pytest.mark.parametrize("bug", sorted(PAGES))
def test_each_view_is_framed_on_the_movers_path_not_on_the_requested_end(pages, bug):
    path, _, _ = pages[bug]
    dom = browser("--dump-dom", path.as_uri()).stdout.decode()
    for svg in re.findall(r'<svg[^>]*class="view".*?</svg>', dom, re.S):
        w, h = (float(x) for x in re.search(r'width="([\d.]+)" height="([\d.]+)"', svg).groups())
        spheres = [(float(x), float(y)) for x, y in re.findall(
            r'<circle class="sphere (?:begin|step \w+|end \w+)" cx="([-\d.]+)" cy="([-\d.]+)"', svg)]
        xs, ys = [x for x, _ in spheres], [y for _, y in spheres]
        centre = ((min(xs) + max(xs)) / 2 / w, (min(ys) + max(ys)) / 2 / h)
        assert 0.25 <= centre[0] <= 0.75 and 0.25 <= centre[1] <= 0.75, f"the path's centre at {centre} of the view"


def test_a_requested_end_far_from_where_the_mover_went_leaves_the_path_framed(page, tmp_path):
    import dataclasses

    path, e, case = page
    m = case.scene.mover
    far = dataclasses.replace(m.end, frame=dataclasses.replace(m.end.frame, origin=(
        m.end.frame.origin[0] + 60.0, m.end.frame.origin[1], m.end.frame.origin[2])))
    moved = dataclasses.replace(case, scene=case.scene.replace(mover=dataclasses.replace(m, end=far)))
    far_page = tmp_path / "far.html"
    far_page.write_text(explain_page(moved, e, "case.json"), encoding="utf-8")
    test_each_view_is_framed_on_the_movers_path_not_on_the_requested_end({"far": (far_page, e, moved)}, "far")
    assert "outside the view in this direction" in far_page.read_text()
