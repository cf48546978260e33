"""The install maps port/, oracle/, strategies/ under acconform.* and lists every subpackage."""

import tomllib
from pathlib import Path

ROOT = Path(__file__).parent.parent
MAPPED = {"acconform": "acconform", "acconform.port": "port", "acconform.oracle": "oracle", "acconform.strategies": "strategies"}
DATA_PACKAGES = {"acconform.corpus": "tests/data/corpus"}  # data only, no __init__.py


def test_every_package_directory_is_listed_in_pyproject():
    cfg = tomllib.loads((ROOT / "pyproject.toml").read_text())["tool"]["setuptools"]
    listed = set(cfg["packages"])
    assert cfg["package-dir"] == MAPPED | DATA_PACKAGES
    found = set()
    for name, folder in MAPPED.items():
        for init in (ROOT / folder).rglob("__init__.py"):
            rel = init.parent.relative_to(ROOT / folder).parts
            found.add(".".join((name, *rel)))
    missing = found - listed
    assert not missing, f"add these to [tool.setuptools] packages in pyproject.toml: {sorted(missing)}"
    assert not (listed - found - set(DATA_PACKAGES)), f"listed but absent: {sorted(listed - found)}"


def test_no_generic_top_level_names_are_installed():
    cfg = tomllib.loads((ROOT / "pyproject.toml").read_text())["tool"]["setuptools"]
    assert all(p == "acconform" or p.startswith("acconform.") for p in cfg["packages"])
