"""The divergence table is never empty and every row names a test that exists."""

import re
from pathlib import Path

ROOT = Path(__file__).parent.parent


def test_every_divergence_row_names_an_existing_pinning_test():
    rows = [l for l in (ROOT / "docs" / "divergences.md").read_text().splitlines()
            if l.startswith("| `") and not l.startswith("| name")]
    assert rows, "docs/divergences.md lists no divergence"
    for row in rows:
        cells = [c.strip() for c in row.strip("|").split("|")]
        assert len(cells) == 6 and all(cells), f"a row needs name, where, ACE, retail, source and a pinning test: {row}"
        m = re.fullmatch(r"`([^:`]+)::(test_\w+)`", cells[5])
        assert m, f"pinned-by must read `path::test_name`: {cells[5]}"
        path, name = m.groups()
        assert f"def {name}(" in (ROOT / path).read_text(), f"{path} has no {name}"
