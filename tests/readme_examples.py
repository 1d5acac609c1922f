"""The README's examples run as written: every `ballbench` line of its ```sh blocks and every
```python block, in order, in one empty folder, with the built binary first on PATH.

A command must exit with status 0, or with the status its line's comment states ("exit status 1:
..."); a Python block must run without error. The recipe's table is then checked against the
files it read: one row per run, each run ending at its own last step (a run that stopped early is
not dropped), its final kinetic energy from the CSV equal to the JSON's final energy (seed-box: unit
masses, no gravity).

Commands that take minutes are not run here, each for the reason in SLOW (other tests run their
parts); lines of the quick start (scripts/...) are what runs this test.

usage: readme_examples.py README.md BALLBENCH [SCRATCH_DIR]  (the folder is made in SCRATCH_DIR, or in TMPDIR)
Exits 77 (skipped) where pandas is not installed.
"""
import os
import re
import shutil
import subprocess
import sys
import tempfile

SLOW = {
    "report": "the quick suite takes about 47 minutes (tests/test_report_resume.cpp runs its parts)",
    "match": "the pile over every engine and profile takes over 10 minutes (tests/test_cli.cpp runs match)",
}

try:
    import pandas  # noqa: F401  (the recipe imports it)
except ImportError:
    print("pandas is not installed (Debian: python3-pandas): skipped")
    sys.exit(77)


def blocks(text):
    """(language, body) of each fenced block, in order. A block ends at a line of ``` alone: text after
    the fence on its line makes no closing fence (CommonMark), so the block would run on to the end."""
    return re.findall(r"^```(\w*)\n(.*?)^```[ \t]*$", text, flags=re.S | re.M)


def expected_status(line):
    m = re.search(r"#.*exit status (\d+)", line)
    return int(m.group(1)) if m else 0


def main():
    readme, binary = sys.argv[1], os.path.abspath(sys.argv[2])
    scratch = sys.argv[3] if len(sys.argv) > 3 else None
    if scratch:
        os.makedirs(scratch, exist_ok=True)
    work = tempfile.mkdtemp(prefix="readme.", dir=scratch)
    env = dict(os.environ, PATH=os.path.dirname(binary) + os.pathsep + os.environ["PATH"])
    failures, ran, namespace = [], 0, {}
    for lang, body in blocks(open(readme).read()):
        if lang == "python":
            cwd = os.getcwd()
            os.chdir(work)
            try:
                exec(compile(body, "README.md python block", "exec"), namespace)
                ran += 1
            except Exception as e:  # the block as written fails: say which and why
                failures.append(f"python block starting {body.splitlines()[0]!r}: {type(e).__name__}: {e}")
            finally:
                os.chdir(cwd)
            continue
        if lang != "sh":
            continue
        for line in body.splitlines():
            words = line.split()
            if len(words) < 2 or words[0] != "ballbench":
                continue
            if words[1] in SLOW:
                print(f"not run: {line.split('#')[0].strip()}: {SLOW[words[1]]}")
                continue
            proc = subprocess.run(["bash", "-c", line], cwd=work, env=env, capture_output=True, text=True)
            ran += 1
            want = expected_status(line)
            if proc.returncode != want:
                failures.append(f"{line.split('#')[0].strip()}: exit status {proc.returncode}, the README says "
                                f"{want}: {proc.stderr.strip()[-400:]}")
    if "table" not in namespace:
        failures.append("the recipe made no `table`")
    else:
        import json
        table = namespace["table"]
        runs = json.load(open(os.path.join(work, "out.json")))
        if len(table) != len(runs):
            failures.append(f"the recipe's table has {len(table)} rows for {len(runs)} runs")
        if len({r["steps_done"] for r in runs}) < 2:
            failures.append("the example's runs all end at the same step: nothing checks runs of different lengths")
        for r in runs:
            key = (r["engine"], r["profile"])
            if key not in table.index:
                failures.append(f"{key}: not in the recipe's table")
                continue
            kinetic, energy = table.loc[key, "kinetic"], r["energy"]["final"]
            if not abs(kinetic - energy) <= 1e-9 * abs(energy):
                failures.append(f"{key}: kinetic energy {kinetic!r} at its last sample, energy.final {energy!r}")
    print("\n".join(failures) or f"{ran} README examples ran as written")
    if not failures:
        shutil.rmtree(work)  # kept for a look when something failed
    sys.exit(1 if failures else 0)


main()
