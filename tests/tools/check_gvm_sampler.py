#!/usr/bin/python3
"""gvm_sampler as a user runs it, on a part with through holes: its rows agree with
`gvm analyze` on the part, and the sampler loses what no lattice can hit.

usage: check_gvm_sampler.py GVM_SAMPLER GVM PART SCRATCH_DIR
"""
import json
import os
import subprocess
import sys


def main():
    sampler, gvm, part, scratch = sys.argv[1:5]
    os.makedirs(scratch, exist_ok=True)
    rows = os.path.join(scratch, "sampler.json")
    analysis_json = os.path.join(scratch, "analysis.json")
    subprocess.run([sampler, part, "--directions", "500,2000", "--json", rows], check=True, stdout=subprocess.DEVNULL)
    subprocess.run([gvm, "analyze", part, "--json", analysis_json], check=True, stdout=subprocess.DEVNULL,
                   stderr=subprocess.DEVNULL)
    bench = json.load(open(rows))
    analysis = json.load(open(analysis_json))
    failures = []

    def expect(ok, what):
        if not ok:
            failures.append(what)

    expect(len(bench["parts"]) == 1, "one row per part")
    row = bench["parts"][0]
    features = analysis["features"]
    reachable = [f for f in features if f.get("gvm", {}).get("dimension", -1) >= 0]
    low_dimensional = [f for f in reachable if f["gvm"]["dimension"] < 2]
    expect(row["triangles"] == analysis["part"]["triangles"], "triangles as gvm analyze counts them")
    expect(row["features"] == len(features), "features as gvm analyze finds them")
    expect(row["reachable"] == len(reachable), "reachable features: those with a non-empty GVM")
    expect(len(low_dimensional) > 0, "the part's through holes have GVMs of points or arcs")
    expect(row["withPointsOrArcs"] >= len(low_dimensional), "every GVM of points or arcs counted")
    runs = row["samplers"]
    expect([r["directions"] for r in runs] == [500, 2000], "one run per lattice size, in order")
    for r in runs:
        rays = int(r.get("rays", 0))
        expect(0 < rays < r["directions"] * row["triangles"], f"{r['directions']}: rays from front faces only")
        # A GVM of points and arcs has measure zero: a lattice sees it only by luck.
        expect(r.get("lostFeatures", 0) >= 1, f"{r['directions']}: the through holes are lost")
        expect(r.get("wrongFeatures", 0) >= r.get("lostFeatures", 0), f"{r['directions']}: a lost feature is wrong")
    expect(int(runs[1]["rays"]) > 3 * int(runs[0]["rays"]), "four times the directions, about four times the rays")
    merged = os.path.join(scratch, "merged.json")
    table = subprocess.run([sampler, "--from-json", rows, "--json", merged], check=True, capture_output=True,
                           text=True).stdout
    expect(json.load(open(merged)) == bench, "rows read back and written again unchanged")
    expect(f"| {row['model']} | {row['triangles']} |" in table and "| all 1 parts |" in table,
           "the table of rows read back, with its totals")
    bad = subprocess.run([sampler, part, "--directions", "many"], stdout=subprocess.DEVNULL, stderr=subprocess.PIPE)
    expect(bad.returncode == 2 and b"usage" in bad.stderr, "a bad option: exit 2 and the usage")
    for f in failures:
        print("FAILED:", f)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
