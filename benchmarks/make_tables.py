#!/usr/bin/python3
"""The benchmark tables of benchmarks/README.md and the headline table of README.md, made
from the JSON files in benchmarks/results/ (numbers are never copied by hand).

    /usr/bin/python3 benchmarks/make_tables.py [--check]

Rewrites every region of those files between

    <!-- begin table NAME (benchmarks/make_tables.py) -->
    <!-- end table NAME -->

with the table NAME made from the results. With --check, writes nothing and exits 1 when
a file is not what the results make (the test Docs.BenchmarkTables runs it so).

The JSON files are protobuf's JSON mapping of the messages in proto/gvm/v1/benchmark.proto
(or plain JSON written by the Python benchmarks): a field at its default value (0, false,
empty) is left out, so every field is read with its default.
"""
import json
import os
import re
import statistics
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)
RESULTS = os.path.join(HERE, "results")
FILES = [os.path.join(ROOT, "README.md"), os.path.join(HERE, "README.md")]
REGION = re.compile(r"(<!-- begin table (?P<name>[\w-]+) \(benchmarks/make_tables\.py\) -->\n)(?P<body>.*?)"
                    r"(<!-- end table (?P=name) -->)", re.S)


def load(name):
    with open(os.path.join(RESULTS, name)) as f:
        return json.load(f)


def g(obj, *path, default=0):
    """obj[path...], or the proto3 default when a field was left out."""
    for key in path:
        if not isinstance(obj, dict) or key not in obj:
            return default
        obj = obj[key]
    return obj


def num(x):
    """Integers of the JSON (uint64 are strings in protobuf's mapping)."""
    return int(x) if isinstance(x, str) else x


def fmt_s(x):
    return "%.2f" % x if x < 100 else "%.1f" % x


def thousands(x):
    return "{:,}".format(num(x))


def table(header, rows, align=None):
    align = align or ["---"] * len(header)
    out = ["| " + " | ".join(header) + " |", "|" + "|".join(align) + "|"]
    out += ["| " + " | ".join(str(c) for c in row) + " |" for row in rows]
    return "\n".join(out) + "\n"


def right(n, left=1):
    return ["---"] * left + ["---:"] * (n - left)


# --- one table per results file -----------------------------------------------------------

def sampler():
    d = load("sampler.json")
    parts = d["parts"]
    sizes = [g(s, "directions") for s in parts[0]["samplers"]]
    header = ["part", "triangles", "features (reachable, points/arcs)", "exact s"]
    for n in sizes:
        header += ["sampler %s s" % thousands(n), "wrong (lost)"]
    rows, total_exact = [], 0
    totals = [[0, 0, 0] for _ in sizes]
    faster = [0 for _ in sizes]
    for p in parts:
        exact = g(p, "exactSeconds")
        total_exact += exact
        row = [p["model"], g(p, "triangles"), "%d (%d, %d)" % (g(p, "features"), g(p, "reachable"), g(p, "withPointsOrArcs")),
               fmt_s(exact)]
        for k, s in enumerate(p["samplers"]):
            row += [fmt_s(g(s, "seconds")), "%d (%d)" % (g(s, "wrongFeatures"), g(s, "lostFeatures"))]
            totals[k][0] += g(s, "seconds")
            totals[k][1] += g(s, "wrongFeatures")
            totals[k][2] += g(s, "lostFeatures")
            faster[k] += exact < g(s, "seconds")
        rows.append(row)
    last = ["all %d parts" % len(parts), "", "", "%.1f" % total_exact]
    for t in totals:
        last += ["%.1f" % t[0], "%d (%d)" % (t[1], t[2])]
    rows.append(last)
    text = table(header, rows, right(len(header)))
    text += "\nExact faster than the sampler on %s. Machine: %s, %d thread(s).\n" % (
        ", ".join("%d of %d parts at %s directions" % (f, len(parts), thousands(n)) for f, n in zip(faster, sizes)),
        g(d, "machine", default="?"), g(d, "threads"))
    return text


def largest_features():
    d = load("largest-features.json")
    surfaces = d["surfaces"]
    best = {}
    for s in surfaces:  # the largest |S| * |O_S| of each part, in the file's order of parts
        key = s["model"]
        if key not in best or g(s, "s") * g(s, "oS") > g(best[key], "s") * g(best[key], "oS"):
            best[key] = s
    header = ["model", "feature", "#S", "#O_S", "EME #GOM", "EME #Arrng", "#GVM", "EME s", "EME MB",
              "convex #GOM", "convex #Arrng", "convex s", "convex MB", "convex / EME", "same GVM"]
    rows = []
    for s in best.values():
        e, c = s.get("envelope", {}), s.get("convex", {})
        rows.append([s["model"], s["surface"], g(s, "s"), g(s, "oS"), num(g(e, "gom")), num(g(e, "arrangementVertices")),
                     num(g(e, "gvmSize")), "%.3f" % g(e, "seconds"), "%.0f" % g(e, "peakMb"), num(g(c, "gom")),
                     num(g(c, "arrangementVertices")), "%.3f" % g(c, "seconds"), "%.0f" % g(c, "peakMb"),
                     "%.1f" % g(s, "convexOverEnvelope"), "yes" if g(s, "sameGvm", default=False) else "NO"])
    text = table(header, rows, right(len(header), 2))
    env = sum(g(s, "envelope", "seconds") for s in surfaces)
    con = sum(g(s, "convex", "seconds") for s in surfaces)
    same = sum(1 for s in surfaces if g(s, "sameGvm", default=False))
    big = [g(s, "convexOverEnvelope") for s in surfaces if g(s, "s") * g(s, "oS") >= 1e5]
    slowest = max(surfaces, key=lambda s: g(s, "convex", "seconds"))
    text += ("\nAll %d features compared (the %d rows above are each part's largest): %d with the same GVM by "
             "both methods; %.1f s by the envelope, %.0f s by convex decomposition (%.0fx), %.0f s of it %s %s "
             "(%.0fx). Over the %d features with |S| |O_S| >= 10^5 the ratio runs from %.1f to %.0f (median %.1f). "
             "Machine: %s, %d thread(s).\n") % (
        len(surfaces), len(rows), same, env, con, con / env, g(slowest, "convex", "seconds"), slowest["model"],
        slowest["surface"], g(slowest, "convexOverEnvelope"), len(big), min(big), max(big), statistics.median(big),
        g(d, "machine", default="?"), g(d, "threads"))
    return text


def planner():
    d = load("planner.json")
    header = ["part", "features", "reachable", "exact setups (bound)", "greedy", "sampling setups",
              "sampling misses (points/arcs/slivers)", "planar-normal setups, unreachable", "analysis s", "plan s",
              "plan / analysis"]
    rows, proven = [], 0
    for p in d["parts"]:
        optimal = g(p, "optimal", default=False)
        proven += optimal
        analysis = g(p, "analysisSeconds")
        rows.append([p["model"], g(p, "features"), g(p, "reachable"),
                     "%d (%d, %s)" % (g(p, "setups"), g(p, "lowerBound"), "proven" if optimal else "gap"),
                     g(p, "greedySetups"), g(p, "samplingSetups"),
                     "%d/%d/%d" % (g(p, "samplingMissedPoints"), g(p, "samplingMissedArcs"), g(p, "samplingMissedSlivers")),
                     "%d, %d" % (g(p, "planarNormalSetups"), g(p, "planarNormalUnreachable")), "%.2f" % analysis,
                     "%.3f" % g(p, "planSeconds"),
                     "%.1f%%" % (100 * g(p, "planSeconds") / analysis) if analysis else "-"])
    sampled = g(d["parts"][0], "sampledDirections")
    text = table(header, rows, right(len(header)))
    text += ("\nOptimal proven on %d of %d parts. Sampling planner: %s Fibonacci directions, a feature reached at a "
             "sample when its exact GVM holds it. Machine: %s, %d thread(s).\n") % (
        proven, len(rows), thousands(sampled), g(d, "machine", default="?"), g(d, "threads"))
    return text


def plan_variants():
    d = load("plan-variants.json")
    header = ["part", "features", "exact, whole", "within %g" % g(d, "toleranceRadians"), "split, exact",
              "default (both)", "reached only within", "planned in pieces"]

    def cell(v):
        return "%d (%d)" % (g(v, "setups"), g(v, "unreachable"))

    rows = [[p["model"], g(p, "features"), cell(p.get("exactWhole", {})), cell(p.get("within", {})),
             cell(p.get("split", {})), cell(p.get("both", {})), g(p, "both", "reachedWithin"), g(p, "both", "split")]
            for p in d["parts"]]
    text = table(header, rows, right(len(header), 1))
    whole = sum(g(p, "exactWhole", "unreachable") for p in d["parts"])
    both = sum(g(p, "both", "unreachable") for p in d["parts"])
    text += ("\nSetups, and in brackets the features not reached whole. Features not reached whole over the %d parts: "
             "%d exact and whole, %d by default. Machine: %s, %d thread(s).\n") % (
        len(rows), whole, both, g(d, "machine", default="?"), g(d, "threads"))
    return text


def step_parts():
    d = load("step.json")
    header = ["part", "B-rep faces", "triangles before -> after", "setups before -> after",
              "unreachable before -> after", "direction angle (rad)", "node displacement (mm)", "faces left to BRepMesh",
              "s before -> after", "MB before -> after"]
    rows = []
    for p in d["parts"]:
        b, a = p.get("before", {}), p.get("after", {})

        def pair(k, f="%s"):
            return (f + " -> " + f) % (g(b, k), g(a, k))
        rows.append([p["part"], g(a, "brep_faces"), pair("triangles"), pair("setups"), pair("unreachable"),
                     "%.1e" % g(a, "direction_angle_rad"), "%.1e" % g(a, "node_displacement_mm"), g(a, "brepmesh_faces"),
                     pair("seconds", "%.2f"), pair("peak_mb")])
    before = sum(g(p, "before", "unreachable") for p in d["parts"])
    after = sum(g(p, "after", "unreachable") for p in d["parts"])
    text = table(header, rows, right(len(header)))
    text += ("\nBefore: BRepMesh's facets as they come (`--brepmesh-only`); after: the faithful tessellation (the "
             "default). Unreachable B-rep faces over the %d parts: %d before, %d after. `gvm plan PART --threads %d`, "
             "analysis included.\n") % (len(rows), before, after, g(d, "threads"))
    return text


def step_worker():
    d = load("step-worker.json")
    header = ["part", "file kB", "triangles", "reply kB", "in-process s", "worker s", "worker - in-process ms"]
    rows = []
    for p in d["parts"]:
        extra = 1000 * (g(p, "workerSeconds") - g(p, "inProcessSeconds"))
        rows.append([p["model"], "%.0f" % (num(g(p, "fileBytes")) / 1000), g(p, "triangles"),
                     "%.1f" % (num(g(p, "replyBytes")) / 1000), "%.3f" % g(p, "inProcessSeconds"),
                     "%.3f" % g(p, "workerSeconds"), "%.0f" % extra])
    extras = [1000 * (g(p, "workerSeconds") - g(p, "inProcessSeconds")) for p in d["parts"]]
    text = table(header, rows, right(len(header)))
    text += ("\nThe worker adds %.0f-%.0f ms a part (its start-up and the reply). Medians of %d runs each, alternating. "
             "Machine: %s.\n") % (min(extras), max(extras), g(d["parts"][0], "runs"), g(d, "machine", default="?"))
    return text


def daemon():
    d = load("daemon.json")
    header = ["parts", "CLI, in turn", "daemon, %d clients" % g(d, "clients"), "parts/min CLI", "parts/min daemon",
              "tiny part round trip (median, p95)"]
    rows = [[g(d, "parts"), "%.1f s" % g(d, "cliSeconds"), "%.1f s" % g(d, "daemonSeconds"),
             "%.1f" % g(d, "cliPartsPerMinute"), "%.1f" % g(d, "daemonPartsPerMinute"),
             "%.2f ms, %.2f ms" % (g(d, "tinyRoundTripMedianMs"), g(d, "tinyRoundTripP95Ms"))]]
    text = table(header, rows)
    text += "\nTiny part: %s, whose analysis takes %.1f ms in-process. Machine: %s.\n" % (
        g(d, "tinyPart", default="?"), 1000 * g(d, "tinyAnalysisSeconds"), g(d, "machine", default="?"))
    return text


def batch():
    d = load("batch.json")
    header = ["configuration", "parts", "wall time", "parts per minute"]
    rows = [[c["configuration"], g(c, "parts"), "%.1f s" % g(c, "seconds"), "%.2f" % g(c, "parts_per_minute")]
            for c in d["configurations"]]
    text = table(header, rows, right(len(header)))
    t = d.get("one_thread_seconds_per_part", {})
    o = d.get("output", {})
    text += ("\nOne thread, seconds per part: mean %.1f, median %.1f, 90th percentile %.1f, largest %.0f. Output: %d "
             "files, %.0f kB, the largest plan %.0f kB. Machine: %s.\n") % (
        g(t, "mean_seconds"), g(t, "median_seconds"), g(t, "p90_seconds"), g(t, "max_seconds"), g(o, "files"),
        g(o, "bytes") / 1000, g(o, "plan_bytes_max") / 1000, g(d, "machine", default="?"))
    return text


def reports():
    d = load("reports.json")
    header = ["part", "triangles", "setups", "unreachable", "`gvm plan --report`", "report size", "load (median)"]
    rows = [[r["part"], thousands(g(r, "triangles")), g(r, "setups"), g(r, "unreachable"),
             "%.1f s" % g(r, "planAndReportSeconds"), "%.2f MB" % (g(r, "reportBytes") / 1e6),
             "%.1f s" % (g(r, "loadMsMedian") / 1000)] for r in d["rows"]]
    text = table(header, rows, right(len(header)))
    text += "\nLoad: from opening the file to the page ready, median of %d. Machine: %s.\n" % (
        len(d["rows"][0].get("loadMs", [])), g(d, "machine", default="?"))
    return text


# --- the README's headline table ------------------------------------------------------------

def headline():
    rows = []
    s = load("sampler.json")
    exact = sum(g(p, "exactSeconds") for p in s["parts"])
    last = [p["samplers"][-1] for p in s["parts"]]
    rows.append(["exact maps against a ray-casting sampler (Embree), %d shared parts, 1 thread" % len(s["parts"]),
                 "every map exact in %.0f s; the sampler at %s directions %.0f s, %d features wrong, %d lost" % (
                     exact, thousands(g(last[0], "directions")), sum(g(x, "seconds") for x in last),
                     sum(g(x, "wrongFeatures") for x in last), sum(g(x, "lostFeatures") for x in last)),
                 "[sampler](benchmarks/README.md#exact-against-a-ray-casting-sampler-gvm_sampler)"])
    c = load("largest-features.json")["surfaces"]
    env, con = sum(g(x, "envelope", "seconds") for x in c), sum(g(x, "convex", "seconds") for x in c)
    rows.append(["effective Minkowski envelope against convex decomposition (the paper's baseline), the up to 3 "
                 "largest features of each shared part (%d)" % len(c),
                 "%d of %d with the same GVM; %.1f s against %.0f s (%.0fx)" % (
                     sum(1 for x in c if g(x, "sameGvm", default=False)), len(c), env, con, con / env),
                 "[methods](benchmarks/README.md#envelope-against-convex-decomposition-gvm_compare)"])
    p = load("planner.json")["parts"]
    missed = sum(g(x, "samplingMissedPoints") + g(x, "samplingMissedArcs") + g(x, "samplingMissedSlivers") for x in p)
    rows.append(["planner, %d shared parts" % len(p),
                 "optimal proven on %d of %d; a planner sampling %s directions misses %d reachable features" % (
                     sum(1 for x in p if g(x, "optimal", default=False)), len(p), thousands(g(p[0], "sampledDirections")),
                     missed),
                 "[planner](benchmarks/README.md#the-planner-gvm_plan_bench)"])
    v = load("plan-variants.json")["parts"]
    rows.append(["tolerance and automatic split, %d parts" % len(v),
                 "features not reached whole: %d exact and whole, %d by default" % (
                     sum(g(x, "exactWhole", "unreachable") for x in v), sum(g(x, "both", "unreachable") for x in v)),
                 "[plan variants](benchmarks/README.md#tolerance-and-split-gvm_plan_variants)"])
    st = load("step.json")["parts"]
    rows.append(["faithful STEP tessellation, %d STEP parts" % len(st),
                 "unreachable B-rep faces %d with BRepMesh's facets, %d faithful" % (
                     sum(g(x, "before", "unreachable") for x in st), sum(g(x, "after", "unreachable") for x in st)),
                 "[STEP parts](benchmarks/README.md#step-parts-step_partspy)"])
    w = load("step-worker.json")["parts"]
    extras = [1000 * (g(x, "workerSeconds") - g(x, "inProcessSeconds")) for x in w]
    rows.append(["STEP read in its worker process", "%.0f-%.0f ms a part more than in-process" % (min(extras), max(extras)),
                 "[STEP worker](benchmarks/README.md#the-step-worker-gvm_step_worker_cost)"])
    dm = load("daemon.json")
    rows.append(["daemon `gvmd`", "round trip %.1f ms (median, cached part); %.1f parts/min against %.1f by the CLI" % (
        g(dm, "tinyRoundTripMedianMs"), g(dm, "daemonPartsPerMinute"), g(dm, "cliPartsPerMinute")),
        "[daemon](benchmarks/README.md#the-daemon-daemon_throughputpy)"])
    b = {x["configuration"]: x for x in load("batch.json")["configurations"]}
    one = next(x for k, x in b.items() if "1 thread" in k and "mpi" not in k)
    two = next(x for k, x in b.items() if "--jobs 2" in k)
    rows.append(["batch of the %d shared parts, 2 cores" % g(two, "parts"),
                 "%.1f parts/min (`--jobs 2`), %.2fx one thread" % (g(two, "parts_per_minute"),
                                                                    g(one, "seconds") / g(two, "seconds")),
                 "[batches](benchmarks/README.md#batches-batch_throughputpy)"])
    r = max(load("reports.json")["rows"], key=lambda x: g(x, "triangles"))
    rows.append(["HTML report of a %s-triangle part" % thousands(g(r, "triangles")),
                 "%.1f MB, opens in %.1f s" % (g(r, "reportBytes") / 1e6, g(r, "loadMsMedian") / 1000),
                 "[reports](benchmarks/README.md#reports-report_examplesmjs)"])
    return table(["what", "today", "details"], rows)


TABLES = {
    "headline": headline, "sampler": sampler, "largest-features": largest_features, "planner": planner,
    "plan-variants": plan_variants, "step": step_parts, "step-worker": step_worker, "daemon": daemon,
    "batch": batch, "reports": reports,
}


def slug(heading):
    """GitHub's anchor of a Markdown heading."""
    text = re.sub(r"[^\w\- ]", "", heading.strip().lower())
    return text.replace(" ", "-")


def check_links(text, path):
    """Every link of the headline table into benchmarks/README.md names one of its headings."""
    with open(os.path.join(HERE, "README.md"), encoding="utf-8") as f:
        anchors = {slug(m.group(1)) for m in re.finditer(r"^#+ (.*)$", f.read(), re.M)}
    for anchor in re.findall(r"\(benchmarks/README\.md#([\w-]+)\)", text):
        if anchor not in anchors:
            raise SystemExit("%s: link to benchmarks/README.md#%s, which has no such heading" % (path, anchor))


def rewrite(text, path):
    def replace(m):
        name = m.group("name")
        if name not in TABLES:
            raise SystemExit("%s: unknown table '%s' (known: %s)" % (path, name, ", ".join(sorted(TABLES))))
        return m.group(1) + TABLES[name]() + m.group(4)
    return REGION.sub(replace, text)


def main(argv):
    check = "--check" in argv
    stale = []
    for path in FILES:
        with open(path, encoding="utf-8") as f:
            old = f.read()
        new = rewrite(old, path)
        check_links(new, path)
        if new != old:
            stale.append(os.path.relpath(path, ROOT))
            if not check:
                with open(path, "w", encoding="utf-8") as f:
                    f.write(new)
    if check and stale:
        print("not what benchmarks/results/ makes: %s (run /usr/bin/python3 benchmarks/make_tables.py)" % ", ".join(stale))
        return 1
    print("%s: %s" % ("stale" if check and stale else ("rewritten" if stale else "up to date"),
                      ", ".join(stale) if stale else ", ".join(os.path.relpath(p, ROOT) for p in FILES)))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
