"""Starts the real gvmd on a Unix socket in a temporary directory and talks to it with
the real clients: Debian's grpcio (with the stubs generated from proto/) and `gvm --server`.

Paths come from the environment CTest sets: GVMD, GVM (the binaries), GVM_PYTHON_PATH
(generated modules), GVM_CLIENT (service/clients/python/gvm_client.py), GVM_SHARED (../shared).
"""
import json
import os
import shutil
import signal
import subprocess
import sys
import tempfile
import time

sys.path.insert(0, os.environ["GVM_PYTHON_PATH"])

import grpc  # noqa: E402
from grpc_protos.grpc.health.v1 import health_pb2, health_pb2_grpc  # noqa: E402
from gvm.v1 import plan_pb2, service_pb2, service_pb2_grpc  # noqa: E402

GVMD = os.environ["GVMD"]
GVM = os.environ["GVM"]
CLIENT = os.environ["GVM_CLIENT"]
SHARED = os.environ["GVM_SHARED"]
PARTS = os.path.join(SHARED, "data", "parts")
BAD = os.path.join(SHARED, "data", "bad")
CLOCK_TICKS = os.sysconf("SC_CLK_TCK")


def part_path(name):
    return os.path.join(PARTS, name)


def part_message(path, name=None, fmt=None):
    with open(path, "rb") as f:
        data = f.read()
    formats = {".stl": service_pb2.PART_FORMAT_STL, ".off": service_pb2.PART_FORMAT_OFF,
               ".obj": service_pb2.PART_FORMAT_OBJ, ".ply": service_pb2.PART_FORMAT_PLY,
               ".stp": service_pb2.PART_FORMAT_STEP, ".step": service_pb2.PART_FORMAT_STEP}
    if fmt is None:
        fmt = formats[os.path.splitext(path)[1].lower()]
    return service_pb2.Part(data=data, format=fmt, name=name or path)


def without_run_facts(value):
    """The JSON without what differs from run to run: timings, seconds, thread counts."""
    if isinstance(value, dict):
        return {k: without_run_facts(v) for k, v in value.items()
                if k != "timing" and k != "threads" and not k.lower().endswith("seconds")}
    if isinstance(value, list):
        return [without_run_facts(v) for v in value]
    return value


def cli_json(command, path, *options):
    """`gvm COMMAND PATH --json -` run locally, as a dict."""
    out = subprocess.run([GVM, command, path, "--json", "-", *options], check=True,
                         capture_output=True, text=True).stdout
    return json.loads(out)


class Daemon:
    """A gvmd process on a socket in its own temporary directory."""

    def __init__(self, *args, socket_dir=None):
        self.root = tempfile.mkdtemp(prefix="gvmd-test-")
        os.chmod(self.root, 0o700)
        self.socket_dir = socket_dir or os.path.join(self.root, "run")
        self.socket = os.path.join(self.socket_dir, "gvmd.sock")
        self.address = "unix:" + self.socket
        self.log_path = os.path.join(self.root, "gvmd.log")
        self.log = open(self.log_path, "w")
        env = dict(os.environ)
        # Under AddressSanitizer freed memory waits in a 256 MiB quarantine, which would
        # read as growth in the memory checks; a small one keeps RSS meaningful.
        env["ASAN_OPTIONS"] = env.get("ASAN_OPTIONS", "") + ":quarantine_size_mb=8"
        self.process = subprocess.Popen([GVMD, "--listen", self.address, *args], stdout=self.log,
                                        stderr=subprocess.STDOUT, env=env)
        self.channel = None
        self._wait_until_serving()

    def _wait_until_serving(self, seconds=60):
        deadline = time.time() + seconds
        while time.time() < deadline:
            if self.process.poll() is not None:
                raise RuntimeError("gvmd exited with %d:\n%s" % (self.process.returncode, self.log_text()))
            if os.path.exists(self.socket):
                try:
                    status = self.health("gvm.v1.Accessibility", timeout=2)
                    if status == health_pb2.HealthCheckResponse.SERVING:
                        return
                except grpc.RpcError:
                    pass
            time.sleep(0.05)
        raise RuntimeError("gvmd did not start:\n" + self.log_text())

    def log_text(self):
        self.log.flush()
        with open(self.log_path) as f:
            return f.read()

    def new_channel(self):
        return grpc.insecure_channel(self.address, options=[("grpc.max_receive_message_length", -1),
                                                            ("grpc.max_send_message_length", -1)])

    def stub(self):
        if self.channel is None:
            self.channel = self.new_channel()
        return service_pb2_grpc.AccessibilityStub(self.channel)

    def health(self, service="", timeout=5):
        with grpc.insecure_channel(self.address) as channel:
            response = health_pb2_grpc.HealthStub(channel).Check(
                health_pb2.HealthCheckRequest(service=service), timeout=timeout)
            return response.status

    def cpu_seconds(self):
        with open("/proc/%d/stat" % self.process.pid) as f:
            fields = f.read().rsplit(")", 1)[1].split()
        return (int(fields[11]) + int(fields[12])) / CLOCK_TICKS  # utime + stime

    def cpu_use(self, window=1.0):
        """Cores in use over the next `window` seconds."""
        before = self.cpu_seconds()
        time.sleep(window)
        return (self.cpu_seconds() - before) / window

    def rss_mib(self):
        with open("/proc/%d/status" % self.process.pid) as f:
            for line in f:
                if line.startswith("VmRSS:"):
                    return int(line.split()[1]) / 1024.0
        return 0.0

    def signal(self, sig):
        self.process.send_signal(sig)

    def close(self):
        if self.channel is not None:
            self.channel.close()
        if self.process.poll() is None:
            self.process.send_signal(signal.SIGTERM)
            try:
                self.process.wait(timeout=30)
            except subprocess.TimeoutExpired:
                self.process.kill()
                self.process.wait()
        self.log.close()
        shutil.rmtree(self.root, ignore_errors=True)


def plan_request(path, **plan_options):
    return service_pb2.PlanRequest(part=part_message(path), plan_options=plan_pb2.PlanOptions(**plan_options))
