#!/usr/bin/python3
"""examples/plan_part against `gvm plan`: the same part, the same number of setups and the
same proven lower bound, in every mode.

    check_plan_part.py PLAN_PART GVM PART

plan_part prints "setups: N", one line per setup, and "proof: ... fewer than M setups";
`gvm plan PART --mode MODE --json -` writes the gvm.v1.Plan those must match.
"""
import json
import re
import subprocess
import sys


def main(plan_part, gvm, part):
    failures = []
    for mode in ("setup", "rotary", "probe"):
        cli = subprocess.run([gvm, "plan", part, "--mode", mode, "--json", "-"], capture_output=True, text=True)
        if cli.returncode != 0:
            sys.exit("gvm plan --mode %s failed (%d): %s" % (mode, cli.returncode, cli.stderr))
        plan = json.loads(cli.stdout)
        want_setups, want_bound = len(plan.get("setups", [])), plan.get("lowerBound", 0)

        example = subprocess.run([plan_part, part, mode], capture_output=True, text=True)
        print("--- plan_part %s %s (exit %d)\n%s%s" % (part, mode, example.returncode, example.stdout, example.stderr))
        if example.returncode != 0:
            failures.append("%s: plan_part exited %d" % (mode, example.returncode))
            continue
        setups = re.search(r"^setups: (\d+)$", example.stdout, re.M)
        proof = re.search(r"^proof: .* fewer than (\d+) setups", example.stdout, re.M)
        rows = re.findall(r"^  \d+  \(", example.stdout, re.M)
        if not setups or not proof:
            failures.append("%s: no 'setups:' or 'proof:' line in plan_part's output" % mode)
            continue
        got_setups, got_bound = int(setups.group(1)), int(proof.group(1))
        if (got_setups, got_bound, len(rows)) != (want_setups, want_bound, want_setups):
            failures.append("%s: plan_part says %d setups (%d listed), bound %d; gvm plan says %d setups, bound %d"
                            % (mode, got_setups, len(rows), got_bound, want_setups, want_bound))
        else:
            print("%s: %d setups, lower bound %d, as gvm plan" % (mode, got_setups, got_bound))
    if failures:
        sys.exit("\n".join(failures))


if __name__ == "__main__":
    if len(sys.argv) != 4:
        sys.exit(__doc__)
    main(*sys.argv[1:])
