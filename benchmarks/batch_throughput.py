#!/usr/bin/python3
"""Throughput of batches on the shared parts (issue: batches, MPI and Slurm).

    /usr/bin/python3 benchmarks/batch_throughput.py [--build build/release]
        [--out benchmarks/results/batch.json]

Plans every shared part as one batch, one configuration after the other on this machine:
`gvm batch` on 1 thread, on 2 threads one part at a time and two parts at a time, and
`mpirun -n 2 gvm-mpi batch` with 1 thread per rank (when gvm-mpi is built). Reports wall
time and parts per minute of each, the distribution of the time per part (for scaling
estimates), and prints a table for the README.
"""
import argparse
import json
import os
import shutil
import statistics
import subprocess
import sys
import tempfile
import time

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)


def run(command, out):
    shutil.rmtree(out, ignore_errors=True)
    t0 = time.perf_counter()
    r = subprocess.run(command, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True)
    seconds = time.perf_counter() - t0
    with open(os.path.join(out, "summary.json")) as f:
        summary = json.load(f)
    if summary["done"] != len(summary["parts"]):
        sys.exit("not every part was planned: %s\n%s" % (command, r.stderr))
    return seconds, summary


def percentile(values, q):
    values = sorted(values)
    return values[min(len(values) - 1, int(q * len(values)))]


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--build", default=os.path.join(ROOT, "build", "release"))
    parser.add_argument("--out", default=os.path.join(HERE, "results", "batch.json"))
    args = parser.parse_args()
    gvm = os.path.join(args.build, "service", "gvm")
    gvm_mpi = os.path.join(args.build, "service", "gvm-mpi")
    parts_dir = os.path.join(ROOT, "..", "shared", "data", "parts")
    parts = sorted(os.path.abspath(os.path.join(parts_dir, f)) for f in os.listdir(parts_dir) if not f.endswith(".md"))

    work = tempfile.mkdtemp(prefix="gvm-batch-bench-")
    manifest = os.path.join(work, "parts.txt")
    with open(manifest, "w") as f:
        f.write("\n".join(parts) + "\n")
    out = os.path.join(work, "out")
    configs = [("gvm batch, 1 thread", [gvm, "batch", manifest, "--out", out, "--threads", "1"]),
               ("gvm batch, 2 threads, --jobs 1", [gvm, "batch", manifest, "--out", out, "--threads", "2", "--jobs", "1"]),
               ("gvm batch, 2 threads, --jobs 2", [gvm, "batch", manifest, "--out", out, "--threads", "2", "--jobs", "2"])]
    mpirun = shutil.which("mpirun")
    if mpirun and os.path.exists(gvm_mpi):
        configs.append(("mpirun -n 2 gvm-mpi batch, 1 thread per rank",
                        [mpirun, "--allow-run-as-root", "-n", "2", gvm_mpi, "batch", manifest, "--out", out,
                         "--threads", "1"]))
    results = []
    per_part = None
    for name, command in configs:
        seconds, summary = run(command, out)
        results.append({"configuration": name, "parts": len(parts), "seconds": round(seconds, 1),
                        "parts_per_minute": round(60 * len(parts) / seconds, 2)})
        print("%-48s %7.1f s  %6.2f parts/min" % (name, seconds, 60 * len(parts) / seconds), file=sys.stderr)
        if per_part is None:  # one thread: the work of each part alone, and what it writes
            per_part = sorted(p["seconds"] for p in summary["parts"])
            files = [os.path.join(out, f) for f in os.listdir(out)]
            output = {"files": len(files), "bytes": sum(os.path.getsize(f) for f in files),
                      "plan_bytes_max": max(os.path.getsize(f) for f in files if f.endswith(".plan.json"))}
    shutil.rmtree(work, ignore_errors=True)

    distribution = {"parts": len(per_part), "mean_seconds": round(statistics.mean(per_part), 2),
                    "median_seconds": round(statistics.median(per_part), 2),
                    "p90_seconds": round(percentile(per_part, 0.9), 2), "max_seconds": round(max(per_part), 2),
                    "sum_seconds": round(sum(per_part), 1)}
    with open(args.out, "w") as f:
        json.dump({"machine": "%d cores" % os.cpu_count(), "configurations": results,
                   "one_thread_seconds_per_part": distribution, "output": output}, f, indent=2)
        f.write("\n")
    print("| configuration | parts | wall time | parts per minute |\n|---|---:|---:|---:|")
    for r in results:
        print("| %s | %d | %.1f s | %.2f |" % (r["configuration"], r["parts"], r["seconds"], r["parts_per_minute"]))
    print("\none thread, seconds per part: " + json.dumps(distribution))
    print("output of the batch: " + json.dumps(output))


if __name__ == "__main__":
    main()
