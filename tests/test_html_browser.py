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
from acconform.html import IMPL, REF, explain_page, report_page
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


@pytest.fixture(scope="module")
def page(tmp_path_factory):
    from mutants import killing_records

    (rec, got), = killing_records(BUG, 1, branch="transitional_insert:step_down_halves")
    command = f"{sys.executable} {PLANTED} {BUG}"
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
    return path, e


def test_the_explain_page_loads_in_chromium_with_both_views_the_spheres_and_the_divergence_marked(page):
    path, e = page
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
    path, _ = page
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
    path, _ = page
    index = tmp_path / "index.html"
    index.write_text(report_page("failures", [("first divergence: A x", "case-1.json", path.as_uri(), "one"),
                                              ("first divergence: A x", "case-2.json", "", "two"),
                                              ("differs in origin", "case-3.json", "", "three")]))
    dom = browser("--dump-dom", index.as_uri()).stdout.decode()
    assert dom.count('<section class="group">') == 2 and dom.count('<li class="case">') == 3
    assert "3 cases, 2 distinct first divergences" in dom and f'href="{path.as_uri()}"' in dom
