"""The install maps port/, oracle/, strategies/ under acconform.* and lists every subpackage; a wheel works."""

import os
import subprocess
import sys
import tomllib
import zipfile
from pathlib import Path

import pytest

ROOT = Path(__file__).parent.parent
MAPPED = {"acconform": "acconform", "acconform.port": "port", "acconform.oracle": "oracle", "acconform.strategies": "strategies"}
DATA_PACKAGES = {"acconform.corpus": "tests/data/corpus"}  # data only, no __init__.py
# data-only directories inside packages, listed so setuptools does not warn that it skips them
DATA_SUBPACKAGES = {"acconform.corpus.mono", "acconform.corpus.coreclr", "acconform.oracle.facade"}


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
    assert not (listed - found - set(DATA_PACKAGES) - DATA_SUBPACKAGES), f"listed but absent: {sorted(listed - found)}"


def test_no_generic_top_level_names_are_installed():
    cfg = tomllib.loads((ROOT / "pyproject.toml").read_text())["tool"]["setuptools"]
    assert all(p == "acconform" or p.startswith("acconform.") for p in cfg["packages"])


@pytest.mark.slow
def test_a_wheel_installed_acconform_runs_check_on_the_corpus_it_carries(tmp_path):
    """Non-editable: the wheel carries the corpus and Facade.cs; `check` runs from a fresh venv."""
    wheels = os.environ.get("ACCONFORM_WHEELS", "/work/shared/wheels")
    if not Path(wheels).is_dir():
        pytest.skip(f"no local wheel directory {wheels} (set ACCONFORM_WHEELS) to install dependencies from")
    out = tmp_path / "dist"
    subprocess.run([sys.executable, "-m", "pip", "wheel", "-q", "--no-index", "--find-links", wheels, "--no-deps",
                    "-w", str(out), str(ROOT)], check=True, cwd=tmp_path)
    wheel = next(out.glob("acconform-*.whl"))
    names = zipfile.ZipFile(wheel).namelist()
    assert "acconform/oracle/facade/Facade.cs" in names
    for runtime in ("mono", "coreclr"):  # both runtimes' corpora
        assert sum(n.startswith(f"acconform/corpus/{runtime}/") and n.endswith(".jsonl.gz") for n in names) >= 3
    venv = tmp_path / "venv"
    subprocess.run([sys.executable, "-m", "venv", str(venv)], check=True)
    subprocess.run([str(venv / "bin" / "pip"), "install", "-q", "--no-index", "--find-links", wheels, str(wheel)],
                   check=True, cwd=tmp_path)
    env = {k: v for k, v in os.environ.items() if k not in ("ACE_ASSEMBLY", "PYTHONPATH")}
    env["XDG_CONFIG_HOME"] = str(tmp_path / "config")
    r = subprocess.run([str(venv / "bin" / "acconform"), "check", "-n", "30", "--seed", "1", "--no-progress",
                        "--failures", str(tmp_path / "f")], capture_output=True, text=True, cwd=tmp_path, env=env)
    assert r.returncode == 0, r.stdout + r.stderr
    assert "30 cases" in r.stdout and "coreclr arithmetic" in r.stderr
    r = subprocess.run([str(venv / "bin" / "acconform"), "check", "-n", "30", "--seed", "1", "--no-progress",
                        "--runtime", "mono", "--failures", str(tmp_path / "f")], capture_output=True, text=True,
                       cwd=tmp_path, env=env)
    assert r.returncode == 0 and "mono arithmetic" in r.stderr, r.stdout + r.stderr
    where = subprocess.run([str(venv / "bin" / "python"), "-c", "from acconform.oracle import default_corpus; "
                            "print(default_corpus())"], capture_output=True, text=True, cwd=tmp_path, env=env)
    assert where.stdout.strip().endswith("acconform/corpus/coreclr") and str(ROOT) not in where.stdout, where
