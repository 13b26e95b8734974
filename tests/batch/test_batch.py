"""gvm batch and gvm-mpi batch, run as a user runs them: real processes, real parts,
killed and resumed for real; every plan compared with `gvm plan` on the same part.

Environment: GVM (the gvm binary), GVM_MPI (gvm-mpi, empty when not built), MPIRUN,
GVM_SHARED (../shared).
"""
import csv
import json
import os
import shutil
import signal
import subprocess
import tempfile
import time
import unittest

GVM = os.environ["GVM"]
GVM_MPI = os.environ.get("GVM_MPI", "")
MPIRUN = os.environ.get("MPIRUN", "") or shutil.which("mpirun") or ""
SHARED = os.environ["GVM_SHARED"]
PARTS = os.path.join(SHARED, "data", "parts")
BAD = os.path.join(SHARED, "data", "bad")

ALL_PARTS = sorted(os.path.join(PARTS, f) for f in os.listdir(PARTS) if not f.endswith(".md"))
BAD_PARTS = [os.path.join(BAD, "prusa_endstop-block_FLIPPED.off"), os.path.join(BAD, "trimesh_multibody.stl")]
# Parts that take a tenth of a second to a second each: the tests of the batch's logic
# (resume, scheduling, MPI, Slurm) run them, under the sanitizers too.
TINY_PARTS = [os.path.join(PARTS, f) for f in (
    "occt_brep_Pump_Nut.off", "occt_shape.stl", "trimesh_plate_holes.STL", "trimesh_round.stl",
    "prusa_endstop-block.stl", "occt_brep_mal_tige.off", "trimesh_20mm-xyz-cube.stl", "prusa_plug-aligner.stl",
    "trimesh_7_8ths_cube.stl")]

TIMING_KEYS = {"timing", "analysisSeconds", "seconds", "startedAt", "finishedAt", "host"}


def without_timings(value):
    """The JSON with every timing (and where it ran) removed: what must be equal."""
    if isinstance(value, dict):
        return {k: without_timings(v) for k, v in value.items() if k not in TIMING_KEYS}
    if isinstance(value, list):
        return [without_timings(v) for v in value]
    return value


def load(path):
    with open(path) as f:
        return json.load(f)


def stem(path):
    return os.path.splitext(os.path.basename(path))[0]


def write_manifest(directory, parts, name="parts.txt"):
    path = os.path.join(directory, name)
    with open(path, "w") as f:
        f.write("# parts of a test batch\n\n" + "\n".join(parts) + "\n")
    return path


def batch(manifest, out, *options, check=None):
    r = subprocess.run([GVM, "batch", manifest, "--out", out, *options], capture_output=True, text=True, timeout=3600)
    if check is not None and r.returncode != check:
        raise AssertionError(f"gvm batch exited {r.returncode}, expected {check}\n{r.stdout}\n{r.stderr}")
    return r


def records(out):
    return {f[: -len(".result.json")]: load(os.path.join(out, f)) for f in os.listdir(out) if f.endswith(".result.json")}


class BatchCase(unittest.TestCase):
    def setUp(self):
        self.dir = tempfile.mkdtemp(prefix="gvm-batch-")

    def tearDown(self):
        shutil.rmtree(self.dir, ignore_errors=True)

    def assert_plan_equals_gvm_plan(self, out, part, *options):
        ref = os.path.join(self.dir, "ref.json")
        subprocess.run([GVM, "plan", part, "--json", ref, "-q", *options], check=True, timeout=3600)
        self.assertEqual(without_timings(load(os.path.join(out, stem(part) + ".plan.json"))),
                         without_timings(load(ref)), f"plan of {part}")


class AllSharedParts(BatchCase):
    def test_every_good_part_is_planned_as_gvm_plan_plans_it(self):
        manifest = write_manifest(self.dir, ALL_PARTS + BAD_PARTS)
        out = os.path.join(self.dir, "out")
        r = batch(manifest, out, "--jobs", "2", "--threads", "2", check=1)
        summary = load(os.path.join(out, "summary.json"))
        by_name = {p["name"]: p for p in summary["parts"]}
        self.assertEqual(len(by_name), len(ALL_PARTS) + len(BAD_PARTS))
        self.assertEqual(summary["done"], len(ALL_PARTS))
        self.assertEqual(summary["failed"], len(BAD_PARTS))
        for bad in BAD_PARTS:
            p = by_name[stem(bad)]
            self.assertEqual(p["status"], "BATCH_STATUS_FAILED")
            self.assertIn(bad, p["error"])  # the message names the file and what is wrong
            self.assertIn(f"failed {stem(bad)}: {bad}", r.stdout)
            self.assertFalse(os.path.exists(os.path.join(out, stem(bad) + ".plan.json")))
        with open(os.path.join(out, "summary.csv")) as f:
            rows = {row["name"]: row for row in csv.DictReader(f)}
        for part in ALL_PARTS:
            p = by_name[stem(part)]
            self.assertEqual(p["status"], "BATCH_STATUS_DONE", p.get("error"))
            plan = load(os.path.join(out, p["planFile"]))
            self.assertEqual(p["setups"], len(plan["setups"]))
            self.assertEqual(rows[stem(part)]["setups"], str(len(plan["setups"])))
            self.assertEqual(rows[stem(part)]["status"], "done")
            self.assert_plan_equals_gvm_plan(out, part, "--threads", "2")


class Resume(BatchCase):
    def test_a_killed_batch_resumed_does_only_the_rest(self):
        manifest = write_manifest(self.dir, TINY_PARTS)
        out = os.path.join(self.dir, "out")
        proc = subprocess.Popen([GVM, "batch", manifest, "--out", out, "--threads", "1"],
                                stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
        # Kill it (as the OOM killer or a node failure would) once a few parts are done.
        deadline = time.time() + 600
        while time.time() < deadline and proc.poll() is None:
            done = [n for n, r in records(out).items() if r["status"] == "BATCH_STATUS_DONE"] if os.path.isdir(out) else []
            if len(done) >= 3:
                break
            time.sleep(0.02)
        proc.kill()
        proc.wait()
        before = records(out)
        done_before = {n for n, r in before.items() if r["status"] == "BATCH_STATUS_DONE"}
        running = {n for n, r in before.items() if r["status"] == "BATCH_STATUS_RUNNING"}
        self.assertGreaterEqual(len(done_before), 3)
        self.assertLess(len(done_before), len(TINY_PARTS), "the batch ended before it was killed")
        self.assertFalse(os.path.exists(os.path.join(out, "summary.json")))
        plans_before = {n: open(os.path.join(out, n + ".plan.json"), "rb").read() for n in done_before}

        r = batch(manifest, out, "--threads", "1", "--resume", check=0)
        after = records(out)
        summary = load(os.path.join(out, "summary.json"))
        self.assertEqual(summary["done"], len(TINY_PARTS))
        self.assertEqual(summary["skipped"], len(done_before))
        self.assertIn(f"({len(done_before)} done before)", r.stdout)
        for name in done_before:  # not run again: record and plan untouched
            self.assertEqual(after[name], before[name])
            self.assertEqual(open(os.path.join(out, name + ".plan.json"), "rb").read(), plans_before[name])
        for name in set(after) - done_before:
            self.assertEqual(after[name]["status"], "BATCH_STATUS_DONE")
            self.assertEqual(after[name]["attempts"], 2 if name in running else 1)
        for part in (TINY_PARTS[0], TINY_PARTS[-1]):  # one done before the kill, one after
            self.assert_plan_equals_gvm_plan(out, part, "--threads", "1")

        # Changed options are a different input: everything runs again.
        r = batch(manifest, out, "--threads", "1", "--resume", "--concave-only", check=0)
        self.assertEqual(load(os.path.join(out, "summary.json"))["skipped"], 0)

    def test_sigterm_interrupts_the_running_part_and_resume_finishes(self):
        # The largest part starts first and takes ten times longer than the tiny ones (10 s
        # against 0.03-5.5 s planned), so it is still running when the first tiny one is
        # done and the signal comes (with tiny parts only, a busy machine can deliver it
        # between two parts, when none runs).
        long_one = os.path.join(PARTS, "prusa_x-end-idler.stl")
        manifest = write_manifest(self.dir, [long_one] + TINY_PARTS)
        out = os.path.join(self.dir, "out")
        proc = subprocess.Popen([GVM, "batch", manifest, "--out", out, "--threads", "1", "--jobs", "2"],
                                stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
        while proc.poll() is None and not (os.path.isdir(out) and any(
                r["status"] == "BATCH_STATUS_DONE" for r in records(out).values())):
            time.sleep(0.02)
        proc.send_signal(signal.SIGTERM)
        stdout, stderr = proc.communicate(timeout=60)
        self.assertEqual(proc.returncode, 128 + signal.SIGTERM, stdout + stderr)
        summary = load(os.path.join(out, "summary.json"))
        statuses = [p.get("status", "BATCH_STATUS_UNSPECIFIED") for p in summary["parts"]]
        self.assertIn("BATCH_STATUS_INTERRUPTED", statuses)
        self.assertEqual(records(out)["prusa_x-end-idler"]["status"], "BATCH_STATUS_INTERRUPTED")
        self.assertNotIn("BATCH_STATUS_RUNNING", [r["status"] for r in records(out).values()])
        self.assertIn("--resume goes on", stdout)
        batch(manifest, out, "--threads", "1", "--resume", check=0)
        self.assertEqual(load(os.path.join(out, "summary.json"))["done"], len(TINY_PARTS) + 1)


class Scheduling(BatchCase):
    def test_largest_first_and_the_memory_bound_keeps_parts_apart(self):
        parts = TINY_PARTS[:6]
        manifest = write_manifest(self.dir, parts)
        out = os.path.join(self.dir, "out")
        # 41 MB leaves 1 MB beside the process's 40 MB, less than any part's estimate: one
        # part at a time (one always runs), however many jobs.
        batch(manifest, out, "--jobs", "3", "--threads", "2", "--max-memory", "41M", check=0)
        runs = sorted(records(out).values(), key=lambda r: r["startedAt"])
        self.assertEqual([r["name"] for r in runs],
                         [r["name"] for r in sorted(runs, key=lambda r: -int(r["inputBytes"]))])
        for a, b in zip(runs, runs[1:]):
            self.assertLessEqual(a["finishedAt"], b["startedAt"], f"{a['name']} and {b['name']} overlap")

    def test_a_part_over_its_timeout_is_recorded_and_the_batch_goes_on(self):
        # The slowest shared part, 14 s on one thread in a release build, and a cube of a
        # few hundredths of a second: 2 s tells them apart on a machine several times
        # faster, and under the sanitizers. (A faster engine moved prusa_y-rod-holder,
        # once 44 s, under the 5 s this test had.)
        slow = os.path.join(PARTS, "occt_TR12J_OCC.stl")
        quick = os.path.join(PARTS, "trimesh_7_8ths_cube.stl")
        out = os.path.join(self.dir, "out")
        r = batch(write_manifest(self.dir, [slow, quick]), out, "--part-timeout", "2", "--threads", "1", check=1)
        got = records(out)
        self.assertEqual(got["occt_TR12J_OCC"]["status"], "BATCH_STATUS_TIMED_OUT")
        self.assertIn("part timeout", got["occt_TR12J_OCC"]["error"])
        self.assertEqual(got["trimesh_7_8ths_cube"]["status"], "BATCH_STATUS_DONE")
        self.assertIn("timed out occt_TR12J_OCC", r.stdout)


class Manifests(BatchCase):
    def test_csv_and_json_manifests_carry_per_part_options(self):
        a = os.path.join(PARTS, "trimesh_plate_holes.STL")
        b = os.path.join(PARTS, "occt_brep_mal_tige.off")
        os.symlink(PARTS, os.path.join(self.dir, "parts"))
        with open(os.path.join(self.dir, "m.csv"), "w") as f:
            f.write('part,name,mode,cone_degrees,concave_only\n'
                    'parts/trimesh_plate_holes.STL,"plate, probed",probe,3,\n'
                    f'{b},,,,true\n')
        out_csv = os.path.join(self.dir, "csv")
        batch(os.path.join(self.dir, "m.csv"), out_csv, "--threads", "1", check=0)
        probe = load(os.path.join(out_csv, "plate, probed.plan.json"))
        self.assertEqual(probe["mode"], "PLAN_MODE_PROBE")
        ref = os.path.join(self.dir, "ref.json")
        subprocess.run([GVM, "plan", os.path.join(self.dir, "parts", "trimesh_plate_holes.STL"), "--mode", "probe",
                        "--cone", "3", "--threads", "1", "-q", "--json", ref], check=True)
        self.assertEqual(without_timings(probe), without_timings(load(ref)))
        self.assert_plan_equals_gvm_plan(out_csv, b, "--concave-only", "--threads", "1")

        manifest = {"parts": [{"part": a, "plan": {"mode": "PLAN_MODE_ROTARY"}}, {"part": b, "name": "tige"}]}
        with open(os.path.join(self.dir, "m.json"), "w") as f:
            json.dump(manifest, f)
        out_json = os.path.join(self.dir, "json")
        batch(os.path.join(self.dir, "m.json"), out_json, "--threads", "1", "--analysis", check=0)
        self.assertEqual(load(os.path.join(out_json, "trimesh_plate_holes.plan.json"))["mode"], "PLAN_MODE_ROTARY")
        self.assertEqual(load(os.path.join(out_json, "tige.analysis.json"))["part"]["source"], b)

    def test_the_readmes_example_manifest(self):
        example = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "data", "example-batch.csv")
        out = os.path.join(self.dir, "out")
        r = batch(example, out, check=0)
        self.assertIn("done        3", r.stdout)
        self.assertEqual(load(os.path.join(out, "featuretype-probed.plan.json"))["mode"], "PLAN_MODE_PROBE")
        self.assertEqual(load(os.path.join(out, "featuretype-milled.plan.json"))["mode"], "PLAN_MODE_SETUP")
        self.assertEqual(load(os.path.join(out, "pmi1.plan.json"))["part"]["fileUnit"], "millimetre")

    def test_bad_manifests_and_options_are_refused_before_any_work(self):
        part = os.path.join(PARTS, "trimesh_round.stl")
        cases = {
            "unknown.csv": ("part,colour\n" + part + ",red\n", "line 2: column 'colour' is neither"),
            "value.csv": ("part,mode\n" + part + ",drill\n", "line 2: column 'mode' needs one of PLAN_MODE_SETUP"),
            "cells.csv": ("part,name\n" + part + "\n", "line 2: 1 cells, the header has 2"),
            "quote.csv": ('part\n"' + part + "\n", "line 2: a quote is never closed"),
            "nopart.csv": ("name\nx\n", "has no column 'part'"),
            "same.txt": (part + "\n" + part + "\n", "line 1 and line 2 both write 'trimesh_round'"),
            "empty.txt": ("# nothing\n", "lists no parts"),
            "bad.json": ('{"parts": [{"part": 3}]}', "not a BatchManifest in JSON"),
            "cone.json": ('{"parts": [{"part": "%s", "plan": {"coneDegrees": -1}}]}' % part, "parts[0]: cone_degrees"),
        }
        for name, (text, message) in cases.items():
            path = os.path.join(self.dir, name)
            with open(path, "w") as f:
                f.write(text)
            out = os.path.join(self.dir, "out-" + name)
            r = batch(path, out, check=2)
            self.assertIn(message, r.stderr, name)
            self.assertFalse(os.path.exists(out), name)
        r = subprocess.run([GVM, "batch", self.dir, "--out", os.path.join(self.dir, "o")], capture_output=True, text=True)
        self.assertEqual(r.returncode, 2)
        self.assertIn("is a directory, not a file", r.stderr)
        manifest = write_manifest(self.dir, [part])
        for options, message in [((), "needs --out"), (("--out", self.dir, "--jobs", "0"), "--jobs needs"),
                                 (("--out", self.dir, "--max-memory", "lots"), "--max-memory needs"),
                                 (("--out", self.dir, "--part-timeout", "-1"), "--part-timeout needs"),
                                 (("--out", self.dir, "--cone", "-5", "--mode", "probe"), "--cone")]:
            r = subprocess.run([GVM, "batch", manifest, *options], capture_output=True, text=True)
            self.assertEqual(r.returncode, 2, options)
            self.assertIn(message, r.stderr, options)


@unittest.skipUnless(GVM_MPI and MPIRUN, "Open MPI is not installed (gvm-mpi not built)")
class Mpi(BatchCase):
    def test_mpirun_gives_the_results_of_gvm_batch(self):
        parts = TINY_PARTS[:6] + BAD_PARTS[:1]
        manifest = write_manifest(self.dir, parts)
        here, there = os.path.join(self.dir, "batch"), os.path.join(self.dir, "mpi")
        batch(manifest, here, "--threads", "1", check=1)
        r = subprocess.run([MPIRUN, "--allow-run-as-root", "--oversubscribe", "-n", "3", GVM_MPI, "batch", manifest,
                            "--out", there, "--threads", "1"], capture_output=True, text=True, timeout=3600)
        self.assertNotEqual(r.returncode, 0, "a bad part: the batch must say it failed")
        self.assertIn("3 ranks", r.stdout)
        names = sorted(f for f in os.listdir(here) if not f.startswith("summary"))
        self.assertEqual(names, sorted(f for f in os.listdir(there) if not f.startswith("summary")))
        for f in names:
            self.assertEqual(without_timings(load(os.path.join(here, f))), without_timings(load(os.path.join(there, f))), f)
        s_here, s_there = load(os.path.join(here, "summary.json")), load(os.path.join(there, "summary.json"))
        self.assertEqual(without_timings(s_here["parts"]), without_timings(s_there["parts"]))
        self.assertEqual((s_there["done"], s_there["failed"], s_there["ranks"]), (len(parts) - 1, 1, 3))
        ranks = {rec["host"].rsplit(" ", 1)[-1] for rec in records(there).values()}
        self.assertGreaterEqual(len(ranks), 2, "rank 0 handed out no part")

    def test_bad_options_are_refused_by_every_rank(self):
        manifest = write_manifest(self.dir, TINY_PARTS[:1])
        r = subprocess.run([MPIRUN, "--allow-run-as-root", "--oversubscribe", "-n", "2", GVM_MPI, "batch", manifest,
                            "--out", os.path.join(self.dir, "o"), "--jobs", "2"], capture_output=True, text=True,
                           timeout=600)
        self.assertNotEqual(r.returncode, 0)
        self.assertEqual(r.stderr.count("--jobs: each rank runs one part at a time"), 1, r.stderr)


SLURM = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "service", "slurm")


class Slurm(BatchCase):
    """The recipes of service/slurm run as Slurm would run them (its variables set by
    hand): every part planned exactly once, as gvm batch plans it."""

    def test_array_tasks_share_the_manifest_out_exactly_once(self):
        parts = TINY_PARTS[:5] + BAD_PARTS[:1]
        os.symlink(PARTS, os.path.join(self.dir, "parts"))
        lines = ["# relative and absolute paths", "parts/" + os.path.basename(parts[0]), ""] + parts[1:]
        with open(os.path.join(self.dir, "m.txt"), "w") as f:
            f.write("\n".join(lines) + "\n")
        out = os.path.join(self.dir, "out")
        for task in (1, 2, 3):  # --array=1-3
            env = dict(os.environ, SLURM_ARRAY_TASK_ID=str(task), SLURM_ARRAY_TASK_MIN="1", SLURM_ARRAY_TASK_COUNT="3",
                       SLURM_CPUS_PER_TASK="1")
            r = subprocess.run(["bash", os.path.join(SLURM, "gvm-batch-array.sbatch"), "m.txt", out],
                               cwd=self.dir, env=env, capture_output=True, text=True, timeout=3600)
            self.assertEqual(r.returncode, 1 if task == 3 else 0, r.stdout + r.stderr)  # the bad part: task 3
        planned = []
        for task in (0, 1, 2):
            chunk = os.path.join(out, "chunk-%d" % task)
            planned += [p["name"] for p in load(os.path.join(chunk, "summary.json"))["parts"]]
        self.assertEqual(sorted(planned), sorted(stem(p) for p in parts))
        linked = os.path.join(self.dir, "parts", os.path.basename(parts[0]))  # as the manifest names it
        self.assert_plan_equals_gvm_plan(os.path.join(out, "chunk-0"), linked, "--threads", "1")

    @unittest.skipUnless(GVM_MPI and MPIRUN, "Open MPI is not installed (gvm-mpi not built)")
    def test_the_mpi_job_script_runs_gvm_mpi_and_resumes(self):
        parts = TINY_PARTS[:4]
        manifest = write_manifest(self.dir, parts)
        out = os.path.join(self.dir, "out")
        env = dict(os.environ, GVM_MPI=GVM_MPI, SLURM_CPUS_PER_TASK="1", OMPI_ALLOW_RUN_AS_ROOT="1",
                   OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1", OMPI_MCA_rmaps_base_oversubscribe="1")
        script = os.path.join(SLURM, "gvm-batch-mpi.sbatch")
        for run in (1, 2):  # the second run is a requeued job: everything done before
            r = subprocess.run(["bash", script, manifest, out], env=env, capture_output=True, text=True, timeout=3600)
            self.assertEqual(r.returncode, 0, r.stdout + r.stderr)
            summary = load(os.path.join(out, "summary.json"))
            self.assertEqual(summary["done"], len(parts))
            self.assertEqual(summary.get("skipped", 0), 0 if run == 1 else len(parts))
        self.assert_plan_equals_gvm_plan(out, parts[0], "--threads", "1")


if __name__ == "__main__":
    unittest.main()
