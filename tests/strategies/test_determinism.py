"""A seed draws the same scenes whatever modules happen to be imported."""

import importlib
import sys

from acconform.strategies import sample_scenes


def test_sample_scenes_do_not_depend_on_which_local_modules_are_imported(tmp_path, monkeypatch):
    # Hypothesis mixes literals from local modules into its draws; a new module full of odd
    # literals must not change what a seed draws.
    before = [s.dumps() for s in sample_scenes(None, 25, 3)]
    (tmp_path / "odd_literals_module.py").write_text(
        "VALUES = [0.6641741394996643, 24.000001, -191.99998, 7919, 1000003, 'EdgeSlide', 0.03999999910593033]\n")
    monkeypatch.syspath_prepend(str(tmp_path))
    importlib.import_module("odd_literals_module")
    try:
        after = [s.dumps() for s in sample_scenes(None, 25, 3)]
    finally:
        sys.modules.pop("odd_literals_module", None)
    assert before == after


def test_the_same_seed_draws_the_same_scenes_twice():
    assert [s.dumps() for s in sample_scenes(None, 10, 11)] == [s.dumps() for s in sample_scenes(None, 10, 11)]
