#!/usr/bin/python3
"""Throughput of gvmd against the command line, on the shared parts (issue: the daemon).

    /usr/bin/python3 benchmarks/daemon_throughput.py [--build build/release] [--clients 4]
        [--parts NAME ...] [--out benchmarks/results/daemon.json]

Plans every part (setup mode) three ways, one after the other on this machine:
  1. `gvm plan PART -q` on each part in turn (a process per part, as a script would);
  2. the same parts through one gvmd, N clients at once (analysis cache off, so that every
     part is computed);
and measures the round trip of a tiny part through the daemon (cached analysis: what the
socket, the messages and the request handling cost) against its in-process time.
Writes a JSON summary and prints a table for the README.
"""
import argparse
import concurrent.futures
import json
import os
import statistics
import subprocess
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--build", default=os.path.join(ROOT, "build", "release"))
    parser.add_argument("--clients", type=int, default=4)
    parser.add_argument("--parts", nargs="*", help="part file names under ../shared/data/parts (default: all)")
    parser.add_argument("--out", default=os.path.join(HERE, "results", "daemon.json"))
    args = parser.parse_args()

    os.environ.setdefault("GVMD", os.path.join(args.build, "service", "gvmd"))
    os.environ.setdefault("GVM", os.path.join(args.build, "service", "gvm"))
    os.environ.setdefault("GVM_PYTHON_PATH", os.path.join(args.build, "python"))
    os.environ.setdefault("GVM_CLIENT", os.path.join(ROOT, "service", "clients", "python", "gvm_client.py"))
    os.environ.setdefault("GVM_SHARED", os.path.join(ROOT, "..", "shared"))
    sys.path.insert(0, os.path.join(ROOT, "tests", "daemon"))
    import harness

    parts = args.parts or sorted(f for f in os.listdir(harness.PARTS) if not f.endswith(".md"))
    paths = [harness.part_path(p) for p in parts]

    t0 = time.perf_counter()
    for p in paths:
        subprocess.run([harness.GVM, "plan", p, "-q"], check=True)
    cli_seconds = time.perf_counter() - t0
    print("CLI, one part after another: %.1f s" % cli_seconds, file=sys.stderr)

    daemon = harness.Daemon("--cache-entries", "0", "--max-jobs", str(args.clients))
    try:
        stub = daemon.stub()
        t0 = time.perf_counter()
        with concurrent.futures.ThreadPoolExecutor(args.clients) as pool:
            plans = list(pool.map(lambda p: stub.Plan(harness.plan_request(p), timeout=3600), paths))
        daemon_seconds = time.perf_counter() - t0
        print("daemon, %d clients: %.1f s" % (args.clients, daemon_seconds), file=sys.stderr)
    finally:
        daemon.close()

    daemon = harness.Daemon()
    try:
        stub = daemon.stub()
        tiny = harness.part_message(harness.part_path("trimesh_7_8ths_cube.stl"))
        request = harness.service_pb2.AnalyzeRequest(part=tiny)
        first = stub.Analyze(request, timeout=60)
        trips = []
        for _ in range(200):
            t = time.perf_counter()
            stub.Analyze(request, timeout=60)
            trips.append(time.perf_counter() - t)
    finally:
        daemon.close()

    summary = {
        "machine": "%d cores" % os.cpu_count(),
        "parts": len(paths),
        "clients": args.clients,
        "cliSeconds": cli_seconds,
        "daemonSeconds": daemon_seconds,
        "cliPartsPerMinute": 60 * len(paths) / cli_seconds,
        "daemonPartsPerMinute": 60 * len(paths) / daemon_seconds,
        "setups": sum(len(p.plan.setups) for p in plans),
        "tinyPart": "trimesh_7_8ths_cube.stl",
        "tinyAnalysisSeconds": first.analysis.timing.total_seconds,
        "tinyRoundTripMedianMs": 1000 * statistics.median(trips),
        "tinyRoundTripP95Ms": 1000 * sorted(trips)[int(0.95 * len(trips))],
    }
    os.makedirs(os.path.dirname(args.out), exist_ok=True)
    with open(args.out, "w") as f:
        json.dump(summary, f, indent=1)
    print("| parts | CLI in turn | daemon, %d clients | parts/min CLI | parts/min daemon | tiny part round trip (median, p95) |"
          % args.clients)
    print("|---|---|---|---|---|---|")
    print("| %d | %.1f s | %.1f s | %.1f | %.1f | %.2f ms, %.2f ms |" % (
        len(paths), cli_seconds, daemon_seconds, summary["cliPartsPerMinute"], summary["daemonPartsPerMinute"],
        summary["tinyRoundTripMedianMs"], summary["tinyRoundTripP95Ms"]))


if __name__ == "__main__":
    main()
