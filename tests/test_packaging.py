"""The install maps port/, oracle/, strategies/ under acconform.* and lists every subpackage; a wheel works;
a checkout imports its own mapped folders whatever acconform is installed beside it."""

import os
import re
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
DATA_SUBPACKAGES = {"acconform.corpus.mono", "acconform.corpus.coreclr", "acconform.oracle.facade",
                    "acconform.oracle.instrument"}


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


def test_a_checkout_imports_acconform_port_oracle_strategies_and_corpus_from_its_own_folders():
    """What `python -m pytest` in a clone does after a plain `pip install .`: the clone's acconform/
    comes first on sys.path, and no editable finder maps port/ etc. (`-S`: no site-packages at all)."""
    code = ("import sys, importlib.util; sys.path.insert(0, sys.argv[1]); import acconform; "
            "print('\\n'.join(f'{n} ' + ' '.join(importlib.util.find_spec(n).submodule_search_locations) "
            "for n in sys.argv[2:]))")
    names = [*MAPPED, *DATA_PACKAGES]
    r = subprocess.run([sys.executable, "-S", "-c", code, str(ROOT), *names], capture_output=True, text=True, cwd="/")
    assert r.returncode == 0, r.stderr
    found = dict(line.split(" ", 1) for line in r.stdout.splitlines())
    for name, folder in (MAPPED | DATA_PACKAGES).items():
        assert Path(found[name]).resolve() == (ROOT / folder).resolve(), (name, found[name])


def test_a_checkout_maps_only_the_folders_pyproject_maps():
    code = "import sys; sys.path.insert(0, sys.argv[1]); import acconform, importlib.util; print(importlib.util.find_spec('acconform.tests'))"
    r = subprocess.run([sys.executable, "-S", "-c", code, str(ROOT)], capture_output=True, text=True, cwd="/")
    assert r.returncode == 0 and r.stdout.strip() == "None", r.stdout + r.stderr


def _readme_setup_commands() -> list[str]:
    block = (ROOT / "README.md").read_text().split("## Set up", 1)[1].split("```sh\n", 1)[1].split("```", 1)[0]
    return [line.split("#", 1)[0].strip() for line in block.splitlines() if line.strip()]


def test_ci_runs_the_readmes_set_up_commands_exactly_as_written():
    commands = _readme_setup_commands()
    assert commands == ['pip install . && acconform check', 'python -m pytest -n auto -m "not slow"']
    ci = (ROOT / ".ci" / "run").read_text()
    lines = [line.strip() for line in ci.splitlines()]
    for cmd in commands:
        assert cmd in lines or f"exec {cmd}" in lines, f".ci/run must run {cmd!r} as the README writes it"
    assert not re.search(r"install[^\n]* -e ", ci), ".ci/run must install as the README does, not editable"
    assert subprocess.run(["bash", "-n", str(ROOT / ".ci" / "run")]).returncode == 0


def test_ci_runs_the_readmes_tests_in_a_venv_of_its_own_before_installing_anything_more():
    """The README's test command must pass with only what `pip install .` installs: .ci/run makes its own
    venv and runs it before it installs an extra (coverage.py, the oracle's pythonnet)."""
    lines = [line.strip() for line in (ROOT / ".ci" / "run").read_text().splitlines() if not line.strip().startswith("#")]
    venv = next(i for i, line in enumerate(lines) if line.startswith("python3 -m venv "))
    setup, tests = lines.index("pip install . && acconform check"), lines.index('python -m pytest -n auto -m "not slow"')
    installs = [i for i, line in enumerate(lines) if "pip install" in line and not line.startswith("echo") and i != setup]
    assert venv < setup < tests
    assert all(i < setup for i in installs if "--upgrade pip" in lines[i])
    assert all(i > tests for i in installs if "--upgrade pip" not in lines[i]), [lines[i] for i in installs]


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
    assert "acconform/oracle/instrument/Instrument.cs" in names and "acconform/oracle/instrument/Recorder.cs" in names
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
    # in the checkout, beside the installed wheel (the README's `python -m pytest`), the checkout's own folders
    here = subprocess.run([str(venv / "bin" / "python"), "-c", "import acconform.port, acconform.corpus; "
                           "print(acconform.port.__file__); print(*acconform.corpus.__path__)"],
                          capture_output=True, text=True, cwd=ROOT, env=env)
    assert here.returncode == 0, here.stderr
    assert here.stdout.split() == [str((ROOT / "port" / "__init__.py").resolve()), str((ROOT / "tests/data/corpus").resolve())]
