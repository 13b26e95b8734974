#!/usr/bin/python3
"""Plans as they were before the planning tolerance and the automatic split: `gvm plan PART
--tolerance 0 --no-split --json` must give the stored plan (tests/data/plans/PART.plan.json,
written by the build before both) value for value, the timings left out and the option
that asks for it (noSplit) taken from the echo.

    check_golden.py GVM GOLDEN_DIR PART...     (parts relative to the working directory)
"""
import json
import os
import subprocess
import sys
import tempfile


def stripped(plan):
    plan.pop("timing", None)
    plan.get("options", {}).pop("noSplit", None)
    return plan


def first_difference(a, b, path="plan"):
    if type(a) is not type(b):
        return f"{path}: {a!r} != {b!r}"
    if isinstance(a, dict):
        for k in sorted(set(a) | set(b)):
            if k not in a or k not in b:
                return f"{path}.{k}: only in {'the golden' if k in a else 'the new plan'}"
            d = first_difference(a[k], b[k], f"{path}.{k}")
            if d:
                return d
        return None
    if isinstance(a, list):
        if len(a) != len(b):
            return f"{path}: {len(a)} entries != {len(b)}"
        for i, (x, y) in enumerate(zip(a, b)):
            d = first_difference(x, y, f"{path}[{i}]")
            if d:
                return d
        return None
    return None if a == b else f"{path}: {a!r} != {b!r}"


def main(argv):
    if len(argv) < 4:
        print(__doc__, file=sys.stderr)
        return 2
    gvm, golden_dir, parts = argv[1], argv[2], argv[3:]
    failed = 0
    with tempfile.TemporaryDirectory() as tmp:
        for part in parts:
            out = os.path.join(tmp, "plan.json")
            run = subprocess.run([gvm, "plan", part, "-q", "--tolerance", "0", "--no-split", "--json", out],
                                 stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True)
            if run.returncode != 0:
                print(f"{part}: gvm failed: {run.stderr.strip()}")
                failed += 1
                continue
            golden = stripped(json.load(open(os.path.join(golden_dir, os.path.basename(part) + ".plan.json"))))
            new = stripped(json.load(open(out)))
            difference = first_difference(golden, new)
            if difference:
                print(f"{part}: differs from the plan before: {difference}")
                failed += 1
            else:
                print(f"{part}: the same plan as before ({len(new.get('setups', []))} setups)")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
