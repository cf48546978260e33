"""The recorded corpus carries exact boundaries (issue 14): at least a tenth of the mono corpus's
records hit one other than a cell or landblock border, counted by the port's trace when the fast
sample was built (tests/runner/corpus_sample.py), and the fast sample replays some of them."""

from __future__ import annotations

from corpus_sample import load_sample

BORDERS = {"boundary:cell_border", "boundary:landblock_border"}


def test_at_least_a_tenth_of_the_mono_corpus_hits_an_exact_boundary_other_than_a_border():
    doc = load_sample("mono")
    assert doc["boundary_records"] >= 0.10 * doc["corpus_records"], (doc["boundary_records"], doc["corpus_records"])


def test_the_fast_sample_replays_records_at_every_exact_boundary_the_corpus_reaches():
    doc = load_sample("mono")
    names = doc["branches"]
    reached = {b for b in names if b.startswith("boundary:") and b not in BORDERS}
    assert {"boundary:floor_z", "boundary:landing_z", "boundary:sphere_tangent"} <= reached
    in_sample = {names[i] for _, _, fired in doc["records"] for i in fired}
    assert reached <= in_sample
