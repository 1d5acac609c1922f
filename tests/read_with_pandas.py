"""The results join in pandas as the README shows: `ballbench run --json` read with
pd.json_normalize, `--trajectory` with pd.read_csv, merged on the columns both have (engine,
profile). Checks that every run has all its samples in the trajectory and that the final sample's
kinetic energy is the JSON's final energy (seed-box: no gravity, unit masses).

usage: read_with_pandas.py RESULTS.json TRAJECTORY.csv
Exits 77 (skipped) where pandas is not installed.
"""
import json
import sys

try:
    import pandas as pd
except ImportError:
    print("pandas is not installed (Debian: python3-pandas): skipped")
    sys.exit(77)

runs = pd.json_normalize(json.load(open(sys.argv[1])))
runs = runs[runs.status != "unsupported"]  # a run the engine refused has no samples
samples = pd.read_csv(sys.argv[2])
joined = samples.merge(runs[["engine", "profile", "n", "steps_done", "energy.final"]], on=["engine", "profile"])
bad = []
for (engine, profile), rows in joined.groupby(["engine", "profile"]):
    run = runs[(runs.engine == engine) & (runs.profile == profile)].iloc[0]
    if len(rows) != run.n * (run.steps_done + 1):
        bad.append(f"{engine}/{profile}: {len(rows)} trajectory rows, expected {run.n} x {run.steps_done + 1}")
    last = rows[rows.step == rows.step.max()]
    kinetic = 0.5 * (last.vx**2 + last.vy**2).sum()
    # The CSV's numbers read back bit for bit; only the order of the sum differs from the harness's,
    # which is round-off of a few ulps on 20 terms: 1e-9 relative is far above it, far below any error.
    if abs(kinetic - run["energy.final"]) > 1e-9 * abs(run["energy.final"]):
        bad.append(f"{engine}/{profile}: final kinetic energy {kinetic!r} from the CSV, {run['energy.final']!r} in the JSON")
if set(map(tuple, runs[["engine", "profile"]].values)) != set(joined.groupby(["engine", "profile"]).groups):
    bad.append("some runs have no trajectory rows")
print("\n".join(bad) or f"{len(runs)} runs joined on engine and profile")
sys.exit(1 if bad else 0)
