"""Record ACE's answers for every per-function spec into data/ace_functions.json.gz (an ACE on
mono) or data/ace_functions_net10.json.gz (an ACE on .NET 10, CoreCLR).

    ACE_ASSEMBLY=/path/to/ACE.Server.dll python tests/port/functions/record_ace_functions.py

The runtime is the configured build's (a .NET build output runs on CoreCLR; --runtime/ACE_RUNTIME
force it). Inputs come from each spec's generator with the seed "recorded" (deterministic), answers
from real ACE through acconform.oracle.functions. The replay test (test_ace_functions.py) runs the
port, computing as that runtime does, on the same inputs on every push, with no ACE. The port's
answers are compared as the data is written and every difference is printed (the data records
ACE, whatever the port says).
"""

from __future__ import annotations

import sys
import time
import warnings
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))

import fn_specs


def record(fns, specs=None) -> dict:
    import numpy as np

    from acconform import __version__
    from acconform.numerics import runtime_named

    runtime = runtime_named(fns.runtime_version)

    doc = {"versions": {"acconform": __version__, "ace": fns.ace_version, "runtime": fns.runtime_version},
           "functions": {}}
    for name, spec in (specs or fn_specs.SPECS).items():
        t0 = time.perf_counter()
        ctx, inputs = fn_specs.generate(spec, "recorded", spec.record_n)
        answers = [fn_specs.plain(spec.ace(fns, ctx, a)) for a in inputs]
        with warnings.catch_warnings(), np.errstate(all="ignore"):
            warnings.simplefilter("ignore")
            count, shown = fn_specs.differences(spec, ctx, inputs, answers, runtime=runtime)
        print(f"{name}: {len(inputs)} inputs, port differs on {count} ({time.perf_counter() - t0:.1f} s)")
        for line in shown:
            print("   ", line)
        doc["functions"][name] = {"context": ctx, "inputs": inputs, "answers": answers}
    return doc


def main() -> int:
    from acconform.oracle.functions import AceFunctions

    from acconform.numerics import runtime_named

    fns = AceFunctions()
    doc = record(fns)
    path = fn_specs.DATA[runtime_named(fns.runtime_version)]
    fn_specs.save(doc, path)
    print(f"wrote {path} ({path.stat().st_size:,} bytes) from {fns.ace_version} on {fns.runtime_version}")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
