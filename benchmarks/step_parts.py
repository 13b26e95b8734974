#!/usr/bin/python3
"""STEP parts planned by two builds of gvm, alternating part by part (the machine's drift
falls on both alike): B-rep faces, triangles, setups, unreachable features, what the
tessellation kept (direction angle, node displacement, faces left to BRepMesh), wall
seconds and peak memory of `gvm plan PART --threads T`. Writes the JSON to OUT and prints
a Markdown table.

    benchmarks/step_parts.py GVM_BEFORE GVM_AFTER OUT.json [--threads T] [PART.stp ...]

Either build may be given as "-" to run one only. Without parts: every good STEP part of
../shared/data/step.
"""
import json
import os
import subprocess
import sys
import tempfile
import time

GOOD = ["bug25169_box-openshell", "bug32745_pmi1", "bm2_ec_lever-A", "bug3883_xr2-ct-214_l-bracket",
        "trj6_k1-pe-203", "bug3883_xr2-ct-214_plate", "r103ec", "trj10_b2-oc-214", "bug27453_165-174_piattello"]


def run(gvm, part, threads):
    with tempfile.TemporaryDirectory() as tmp:
        plan_json, analysis_json, times = (os.path.join(tmp, n) for n in ("plan.json", "analysis.json", "time"))
        start = time.monotonic()
        proc = subprocess.run(["/usr/bin/time", "-f", "%M", "-o", times, gvm, "plan", part, "-q", "--threads",
                               str(threads), "--json", plan_json, "--analysis-json", analysis_json],
                              stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True)
        seconds = time.monotonic() - start
        if proc.returncode != 0:
            return {"error": proc.stderr.strip().splitlines()[-1] if proc.stderr.strip() else "exit %d" % proc.returncode}
        plan, analysis = json.load(open(plan_json)), json.load(open(analysis_json))
        peak_kb = int(open(times).read().split()[-1])
    summary = analysis["part"]
    tess = summary.get("stepTessellation", {})
    return {
        "brep_faces": summary.get("cadFaces", 0),
        "triangles": summary.get("triangles", 0),
        "setups": len(plan.get("setups", [])),
        "unreachable": int(plan.get("unreachableCount", 0)),
        "faithful": tess.get("faithful", False),
        "direction_angle_rad": tess.get("maxDirectionAngleRadians", 0),
        "node_displacement_mm": tess.get("maxNodeDisplacementMm", 0),
        "brepmesh_faces": len(tess.get("brepmeshFaces", [])),
        "inexact_relations": len(tess.get("inexact", [])),
        "seconds": round(seconds, 2),
        "peak_mb": round(peak_kb / 1024),
    }


def cell(r, key, fmt="{}"):
    if r is None:
        return ""
    if "error" in r:
        return "error"
    return fmt.format(r[key])


def main(argv):
    args = [a for a in argv[1:]]
    threads = 2
    if "--threads" in args:
        i = args.index("--threads")
        threads = int(args[i + 1])
        del args[i:i + 2]
    if len(args) < 3:
        print(__doc__, file=sys.stderr)
        return 2
    before, after, out = args[:3]
    parts = args[3:] or [os.path.join("..", "shared", "data", "step", n + ".stp") for n in GOOD]
    rows = []
    for part in parts:
        row = {"part": os.path.basename(part), "threads": threads}
        if before != "-":
            row["before"] = run(before, part, threads)
        if after != "-":
            row["after"] = run(after, part, threads)
        rows.append(row)
        print(json.dumps(row), file=sys.stderr)
    with open(out, "w") as f:
        json.dump({"threads": threads, "parts": rows}, f, indent=1)
    print("| part | B-rep faces | triangles before -> after | setups before -> after | unreachable before -> after "
          "| direction angle (rad) | node displacement (mm) | faces left to BRepMesh | s before -> after | MB before -> after |")
    print("|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|")
    for row in rows:
        b, a = row.get("before"), row.get("after")
        ref = a or b
        print("| %s | %s | %s -> %s | %s -> %s | %s -> %s | %s | %s | %s | %s -> %s | %s -> %s |" % (
            row["part"], cell(ref, "brep_faces"), cell(b, "triangles"), cell(a, "triangles"), cell(b, "setups"),
            cell(a, "setups"), cell(b, "unreachable"), cell(a, "unreachable"), cell(a, "direction_angle_rad", "{:.1e}"),
            cell(a, "node_displacement_mm", "{:.1e}"), cell(a, "brepmesh_faces"), cell(b, "seconds"), cell(a, "seconds"),
            cell(b, "peak_mb"), cell(a, "peak_mb")))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
