#!/usr/bin/python3
"""Sorts what fuzz_step found by where it happened, and fails when any of it is ours.

    classify_step_findings.py --fuzzer build/fuzz/tests/fuzz/fuzz_step \
        --artifacts build/fuzz/tests/fuzz/artifacts [--source DIR] [--json OUT]

fuzz_step runs in fork mode with -ignore_crashes=1, so that Open CASCADE's own crashes
(contained in gvm by the STEP worker) do not end the campaign; but then a crash of ours
would not end it either. This replays every finding (crash-, timeout-, oom-, leak-) once,
takes the innermost frame of its report that is not the sanitizer's or the C library's,
and prints one row per place: kind, owner (Open CASCADE when that frame is in one of its
libTK* libraries, ours when it is in the source tree or the harness reported a broken
invariant), count and one input. Exit status 1 when a finding is ours or cannot be placed.
"""
import argparse
import collections
import json
import os
import re
import subprocess
import sys

FRAME = re.compile(r"^\s*#(\d+) 0x[0-9a-f]+ in (.+?) \(?(/[^ )]+)")
# Frames that place nothing: a library known only by its module (the sanitizers' and
# libFuzzer's runtime linked into the target, libc, libstdc++, oneTBB, GMP) and the standard
# library's inlined templates. The first frame after them is in Open CASCADE or in ours.
INLINED_STD = re.compile(r"^/usr/include/|/lib/gcc/")
KINDS = ("crash", "timeout", "oom", "leak", "slow-unit")


def kind_of(name):
    for k in KINDS:
        if f"-{k}-" in name:
            return k
    return None


def place(report, source):
    """(owner, site) of one replayed finding."""
    if "broken invariant" in report or "unexpected status" in report:
        what = re.search(r"(broken invariant: .*|unexpected status .*)", report).group(1)
        return "ours", what.strip()
    for line in report.splitlines():
        m = FRAME.match(line)
        if not m:
            continue
        function, where = re.sub(r"\(.*$", "", m.group(2)) or m.group(2), m.group(3)
        if "/libTK" in where:
            return "Open CASCADE", f"{function} ({os.path.basename(where).split('+')[0]})"
        if "+0x" in where or INLINED_STD.search(where):
            continue
        if where.startswith(source):
            return "ours", f"{function} ({os.path.relpath(where.split(':')[0], source)})"
        return "other", f"{function} ({where})"
    return "unplaced", "no stack in the report"


def report_of(fuzzer, path):
    env = dict(os.environ, ASAN_OPTIONS="detect_leaks=0:symbolize=1",
               UBSAN_OPTIONS="halt_on_error=1:print_stacktrace=1")
    run = subprocess.run([fuzzer, "-runs=1", "-timeout=25", "-rss_limit_mb=2560", path],
                         env=env, capture_output=True, text=True, errors="replace", timeout=300)
    if run.returncode == 0:
        return None  # no longer reproduces (a timeout on a busy machine, say)
    return run.stderr


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--fuzzer", required=True)
    parser.add_argument("--artifacts", required=True)
    parser.add_argument("--source", default=os.path.dirname(os.path.dirname(os.path.dirname(
        os.path.abspath(__file__)))))
    parser.add_argument("--json")
    args = parser.parse_args()
    source = os.path.abspath(args.source) + "/"

    places = collections.OrderedDict()
    gone = 0
    names = sorted(f for f in os.listdir(args.artifacts)
                   if f.startswith("fuzz_step-") and kind_of(f))
    for name in names:
        report = report_of(args.fuzzer, os.path.join(args.artifacts, name))
        if report is None:
            gone += 1
            continue
        owner, site = place(report, source)
        row = places.setdefault((kind_of(name), owner, site), {"count": 0, "example": name})
        row["count"] += 1

    print(f"{len(names)} findings, {gone} no longer reproduce; by place:")
    print(f"{'kind':8} {'owner':13} {'count':>5}  site  (one input)")
    for (kind, owner, site), row in sorted(places.items(), key=lambda kv: -kv[1]["count"]):
        print(f"{kind:8} {owner:13} {row['count']:5}  {site}  ({row['example']})")
    if args.json:
        with open(args.json, "w") as out:
            json.dump({"findings": len(names), "not_reproduced": gone,
                       "places": [{"kind": k, "owner": o, "site": s, **r}
                                  for (k, o, s), r in places.items()]}, out, indent=1)
    ours = [key for key in places if key[1] not in ("Open CASCADE",)]
    if ours:
        print(f"{len(ours)} place(s) not inside Open CASCADE: these are ours to fix", file=sys.stderr)
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
