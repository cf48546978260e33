"""acconform: a property-based conformance harness for Asheron's Call movement physics.

The Python port (acconform.port) and ACE's own C# physics (acconform.oracle) both take a
Scene and return an Outcome (acconform.scene, acconform.outcome); the runner compares them.
"""

__version__ = "0.1.0"


def _map_checkout() -> None:
    """In a checkout, import acconform.port, .oracle, .strategies and .corpus from the folders
    pyproject.toml maps them from (port/, oracle/, strategies/, tests/data/corpus).

    Why: in a clone, `python -m pytest` (like `python -m` anything) puts the clone's root first on
    sys.path, so `import acconform` finds this folder and not the installed package, and
    `acconform.port` is then looked for only here, where it is not: those four exist as acconform.*
    only through [tool.setuptools.package-dir]. An editable install maps them with a finder of
    setuptools'; after a plain `pip install .` (the README's set-up) nothing did, and the tests
    failed with "No module named 'acconform.port'". This finder does for the checkout what the
    editable one does, read from the same table (the mapping is kept in one place), and maps only
    those names: putting the repository root on __path__ instead would also make acconform.tests,
    acconform.benchmarks, ... importable. It goes first on sys.meta_path, so an editable install of
    another checkout cannot lend this checkout its port. Installed (site-packages/acconform), no
    pyproject.toml of acconform sits beside the package and nothing is mapped.
    """
    import sys
    from pathlib import Path

    root = Path(__file__).resolve().parent.parent
    pyproject = root / "pyproject.toml"
    if not pyproject.is_file():
        return
    import tomllib

    try:
        cfg = tomllib.loads(pyproject.read_text(encoding="utf-8"))
    except (OSError, ValueError):
        return
    if cfg.get("project", {}).get("name") != "acconform":
        return
    folders = {name: root / folder
               for name, folder in cfg.get("tool", {}).get("setuptools", {}).get("package-dir", {}).items()
               if name.startswith("acconform.") and (root / folder).is_dir()}
    if folders and not any(isinstance(f, _CheckoutFinder) and f.folders == folders for f in sys.meta_path):
        sys.meta_path.insert(0, _CheckoutFinder(folders))


class _CheckoutFinder:
    """Finds exactly the mapped packages (name -> folder); their subpackages are found in the folder."""

    def __init__(self, folders):
        self.folders = folders

    def find_spec(self, fullname, path=None, target=None):
        folder = self.folders.get(fullname)
        if folder is None:
            return None
        from importlib.machinery import PathFinder
        from importlib.util import spec_from_file_location

        init = folder / "__init__.py"
        if init.is_file():
            return spec_from_file_location(fullname, init, submodule_search_locations=[str(folder)])
        # data only (the corpus): a namespace package, made as the import system makes one
        return PathFinder.find_spec(fullname, [str(folder.parent)]) if folder.name == fullname.rpartition(".")[2] else None


_map_checkout()
