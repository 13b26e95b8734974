"""STEP files that crash Open CASCADE, make it loop or need more memory than allowed: each
fails its own part, with the reason, through the command line, the daemon (alive and
serving the other clients throughout) and a batch; Open CASCADE runs in gvm-step-worker.

The crashers (tests/data/step-crashers/) and the looping file (tests/data/step-loops/) are
corruptions of shared STEP parts made by tests/step_crashers/corrupt_step.py; SOURCES.md
there says which and where each one crashes.
"""
import concurrent.futures
import json
import os
import shutil
import signal
import subprocess
import tempfile
import time
import unittest

from harness import CLIENT, GVM, SHARED, Daemon, cli_json, grpc, part_message, plan_request, service_pb2, \
    without_run_facts
from google.protobuf import json_format
from gvm.v1 import gvm_pb2

DATA = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "data"))
CRASHERS = sorted(os.path.join(DATA, "step-crashers", f) for f in os.listdir(os.path.join(DATA, "step-crashers"))
                  if f.endswith(".stp"))
LOOP = os.path.join(DATA, "step-loops", "042-number-bug3883_xr2-ct-214_plate.stp")
LOOPS = sorted(os.path.join(DATA, "step-loops", f) for f in os.listdir(os.path.join(DATA, "step-loops"))
               if f.endswith(".stp"))
STEP = os.path.join(SHARED, "data", "step")
GOOD = [os.path.join(STEP, "bug3883_xr2-ct-214_plate.stp"), os.path.join(STEP, "bug3883_xr2-ct-214_l-bracket.stp"),
        os.path.join(SHARED, "data", "parts", "trimesh_20mm-xyz-cube.stl")]
CRASHED = "the STEP reader crashed on this file (signal 11, SIGSEGV)"
SANITIZED = bool(os.environ.get("GVM_SANITIZED"))


def as_dict(message):
    return json.loads(json_format.MessageToJson(message, including_default_value_fields=True))


def analyze_request(path, **step):
    options = gvm_pb2.AnalyzeOptions(lvm_only=True)
    for k, v in step.items():
        setattr(options.step, k, v)
    return service_pb2.AnalyzeRequest(part=part_message(path), options=options)


def workers_of(pid):
    """The daemon's gvm-step-worker children still alive."""
    out = subprocess.run(["pgrep", "-P", str(pid), "-f", "gvm-step-worker"], capture_output=True, text=True).stdout
    return out.split()


class CommandLine(unittest.TestCase):
    def test_crashers_fail_with_the_reason(self):
        for path in CRASHERS:
            run = subprocess.run([GVM, "analyze", path, "--lvm-only", "-q"], capture_output=True, text=True, timeout=120)
            self.assertEqual(run.returncode, 1, path)
            self.assertIn(path + ": " + CRASHED, run.stderr)

    def test_a_looping_file_is_stopped_at_its_cpu_limit(self):
        for path in LOOPS:
            started = time.time()
            run = subprocess.run([GVM, "analyze", path, "--lvm-only", "-q", "--step-seconds", "3"], capture_output=True,
                                 text=True, timeout=120)
            self.assertEqual(run.returncode, 1, path)
            self.assertIn("the STEP reader ran over its CPU time limit of 3 s", run.stderr, path)
            self.assertLess(time.time() - started, 60, path)

    @unittest.skipIf(SANITIZED, "a sanitizer's shadow memory leaves the address space unlimited")
    def test_a_part_over_its_memory_limit_says_so(self):
        part = os.path.join(STEP, "bug27453_165-174_piattello.stp")
        run = subprocess.run([GVM, "analyze", part, "--lvm-only", "-q", "--step-memory", "64"], capture_output=True,
                             text=True, timeout=300)
        self.assertEqual(run.returncode, 1)
        self.assertIn("the STEP reader exceeded its memory limit of 64 MiB", run.stderr)

    def test_limits_out_of_range_are_refused(self):
        for flag, value in (("--step-memory", "10"), ("--step-seconds", "0"), ("--step-seconds", "x")):
            run = subprocess.run([GVM, "analyze", GOOD[0], flag, value], capture_output=True, text=True, timeout=60)
            self.assertEqual(run.returncode, 2, (flag, value, run.stderr))
            self.assertIn(flag, run.stderr)


class InTheDaemon(unittest.TestCase):
    def setUp(self):
        self.daemon = Daemon("--threads", "2", "--max-jobs", "2", "--max-queue", "64")

    def tearDown(self):
        self.daemon.close()

    def test_crashers_in_a_loop_beside_good_parts(self):
        expected = {p: without_run_facts(cli_json("plan", p)) for p in GOOD}
        stub = self.daemon.stub()

        def crash_loop(rounds):
            codes = []
            for _ in range(rounds):
                for path in CRASHERS:
                    try:
                        stub.Analyze(analyze_request(path), timeout=120)
                        codes.append(("answered", path, ""))
                    except grpc.RpcError as e:
                        codes.append((e.code(), path, e.details()))
            return codes

        def good_parts(rounds):
            with self.daemon.new_channel() as channel:
                from gvm.v1 import service_pb2_grpc
                own = service_pb2_grpc.AccessibilityStub(channel)
                return [(p, as_dict(own.Plan(plan_request(p), timeout=600).plan)) for _ in range(rounds) for p in GOOD]

        crash_loop(1)  # the daemon warm: every kind of request seen once
        good_parts(1)
        rss_warm = self.daemon.rss_mib()
        with concurrent.futures.ThreadPoolExecutor(3) as pool:
            crashes = pool.submit(crash_loop, 5)
            goods = [pool.submit(good_parts, 2) for _ in range(2)]
            for f in goods:
                for path, plan in f.result():
                    self.assertEqual(without_run_facts(plan), expected[path], path)
            for code, path, details in crashes.result():
                self.assertEqual(code, grpc.StatusCode.INVALID_ARGUMENT, (path, details))
                self.assertIn(CRASHED, details)
        self.assertIsNone(self.daemon.process.poll(), "the daemon is alive")
        self.assertEqual(workers_of(self.daemon.process.pid), [])
        self.assertLess(self.daemon.rss_mib() - rss_warm, 64, "memory back near where it was")

    def test_a_looping_file_past_its_deadline_frees_its_slot(self):
        with self.assertRaises(grpc.RpcError) as caught:
            self.daemon.stub().Analyze(analyze_request(LOOP), timeout=3)
        self.assertEqual(caught.exception.code(), grpc.StatusCode.DEADLINE_EXCEEDED)
        time.sleep(1.0)  # the promise: stopped within about a second
        self.assertEqual(workers_of(self.daemon.process.pid), [])
        self.assertLess(self.daemon.cpu_use(1.0), 0.3, self.daemon.log_text())
        response = self.daemon.stub().Plan(plan_request(GOOD[0]), timeout=600)
        self.assertGreater(len(response.plan.setups), 0)

    def test_a_looping_file_at_its_cpu_limit_is_resource_exhausted(self):
        with self.assertRaises(grpc.RpcError) as caught:
            self.daemon.stub().Analyze(analyze_request(LOOP, reader_seconds=2), timeout=120)
        self.assertEqual(caught.exception.code(), grpc.StatusCode.RESOURCE_EXHAUSTED)
        self.assertIn("CPU time limit of 2 s", caught.exception.details())

    def test_sigterm_ends_the_daemon_while_workers_loop(self):
        stub = self.daemon.stub()
        calls = [stub.Analyze.future(analyze_request(LOOP), timeout=300) for _ in range(2)]
        time.sleep(2)
        self.assertEqual(len(workers_of(self.daemon.process.pid)), 2)
        started = time.time()
        self.daemon.signal(signal.SIGTERM)
        self.daemon.process.wait(timeout=30)
        self.assertLess(time.time() - started, 15, "within the 10 s grace period")
        for c in calls:
            with self.assertRaises(grpc.RpcError):
                c.result()

    def test_python_client_sends_step(self):
        run = subprocess.run(["/usr/bin/python3", CLIENT, "plan", GOOD[1], "--server", self.daemon.address],
                             capture_output=True, text=True, check=True)
        self.assertEqual(without_run_facts(json.loads(run.stdout)), without_run_facts(cli_json("plan", GOOD[1])))



class InABatch(unittest.TestCase):
    def test_the_batch_finishes_with_the_crashers_failed(self):
        tmp = tempfile.mkdtemp(prefix="gvm-step-batch-")
        try:
            manifest = os.path.join(tmp, "parts.txt")
            with open(manifest, "w") as f:
                f.write("\n".join(GOOD[:2] + CRASHERS + [LOOP]) + "\n")
            out = os.path.join(tmp, "out")
            run = subprocess.run([GVM, "batch", manifest, "--out", out, "--jobs", "2", "--threads", "1",
                                  "--part-timeout", "30"], capture_output=True, text=True, timeout=900)
            self.assertEqual(run.returncode, 1, run.stdout + run.stderr)
            with open(os.path.join(out, "summary.json")) as f:
                parts = {p["name"]: p for p in json.load(f)["parts"]}
            stem = lambda p: os.path.splitext(os.path.basename(p))[0]
            for p in GOOD[:2]:
                self.assertEqual(parts[stem(p)]["status"], "BATCH_STATUS_DONE", parts[stem(p)].get("error"))
            for p in CRASHERS:
                self.assertEqual(parts[stem(p)]["status"], "BATCH_STATUS_FAILED")
                self.assertIn(p + ": " + CRASHED, parts[stem(p)]["error"])
            self.assertEqual(parts[stem(LOOP)]["status"], "BATCH_STATUS_TIMED_OUT")
        finally:
            shutil.rmtree(tmp, ignore_errors=True)


if __name__ == "__main__":
    unittest.main()
