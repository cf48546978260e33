"""Seeds that mean the same scenes whatever else is imported.

Hypothesis (6.13x and later) mixes literals found in the source of every *local* module in
sys.modules into its draws (`providers._get_local_constants`), and caches the mix on first use.
With acconform installed from a checkout every acconform module counts as local, so the scenes a
seed draws changed with which commands happened to be imported (`acconform coverage` and a bare
`sample_scenes` call drew different scenes for seed 0). `pinned_constants()` empties that local
pool for the duration of a draw and restores Hypothesis' state afterwards. It touches Hypothesis
internals, so it checks they are there and otherwise does nothing; tests/strategies pins the
behaviour (draws must not depend on imports), so a Hypothesis change shows up as a failing test.
"""

from __future__ import annotations

from contextlib import contextmanager


@contextmanager
def pinned_constants():
    try:
        from hypothesis.internal.conjecture import providers
    except ImportError:  # pragma: no cover - a Hypothesis without the feature
        yield
        return
    get_local = getattr(providers, "_get_local_constants", None)
    cache = getattr(getattr(providers, "CONSTANTS_CACHE", None), "cache", None)
    local = getattr(providers, "_local_constants", None)
    if get_local is None or cache is None or local is None:  # pragma: no cover
        yield
        return
    empty = type(local)(**{name: type(getattr(local, name))(**_sorted_set_args(getattr(local, name)))
                           for name in ("integers", "floats", "bytes", "strings")})
    saved = dict(cache)
    cache.clear()
    providers._get_local_constants = lambda: empty
    try:
        yield
    finally:
        providers._get_local_constants = get_local
        cache.clear()
        cache.update(saved)


def _sorted_set_args(s) -> dict:
    key = getattr(s, "key", None)
    return {"key": key} if key is not None else {}
