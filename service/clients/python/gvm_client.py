#!/usr/bin/python3
"""A small Python client of gvmd (gvm.v1.Accessibility over gRPC).

    /usr/bin/python3 gvm_client.py plan PART [--server unix:PATH] [--mode setup|rotary|probe] [--timeout SEC]
    /usr/bin/python3 gvm_client.py analyze PART [--server unix:PATH] [--timeout SEC]

prints the Plan (or Analysis) as protobuf's JSON mapping, the same as `gvm plan --json -`.
As a module: `connect(address)` gives a stub; `part_from_file(path)` a gvm.v1.Part.

The gvm.v1 modules are generated at build time into build/<preset>/python; set
GVM_PYTHON_PATH to that directory (default: build/release/python of this checkout).
Runs with Debian's /usr/bin/python3 (python3-grpcio, python3-protobuf).
"""
import argparse
import os
import sys

_HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.environ.get("GVM_PYTHON_PATH", os.path.join(_HERE, "..", "..", "..", "build", "release", "python")))

import grpc  # noqa: E402
from google.protobuf import json_format  # noqa: E402
from gvm.v1 import plan_pb2, service_pb2, service_pb2_grpc  # noqa: E402

FORMATS = {".stl": service_pb2.PART_FORMAT_STL, ".off": service_pb2.PART_FORMAT_OFF,
           ".obj": service_pb2.PART_FORMAT_OBJ, ".ply": service_pb2.PART_FORMAT_PLY,
           ".stp": service_pb2.PART_FORMAT_STEP, ".step": service_pb2.PART_FORMAT_STEP}
MODES = {"setup": plan_pb2.PLAN_MODE_SETUP, "rotary": plan_pb2.PLAN_MODE_ROTARY, "probe": plan_pb2.PLAN_MODE_PROBE}


def default_address():
    runtime = os.environ.get("XDG_RUNTIME_DIR")
    if runtime:
        return "unix:" + os.path.join(runtime, "gvmd.sock")
    return "unix:/tmp/gvmd-%d/gvmd.sock" % os.geteuid()


def connect(address=None):
    """A stub of gvm.v1.Accessibility on the daemon at `address` (unix:PATH or HOST:PORT)."""
    options = [("grpc.max_receive_message_length", -1), ("grpc.max_send_message_length", -1)]
    return service_pb2_grpc.AccessibilityStub(grpc.insecure_channel(address or default_address(), options=options))


def part_from_file(path, name=None):
    """The part's bytes, with the format from the file's extension."""
    with open(path, "rb") as f:
        data = f.read()
    fmt = FORMATS.get(os.path.splitext(path)[1].lower(), service_pb2.PART_FORMAT_UNSPECIFIED)
    return service_pb2.Part(data=data, format=fmt, name=name or path)


def main(argv):
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("command", choices=["plan", "analyze"])
    parser.add_argument("part")
    parser.add_argument("--server", default=None, help="unix:PATH (default: gvmd's default socket)")
    parser.add_argument("--mode", choices=sorted(MODES), default="setup")
    parser.add_argument("--timeout", type=float, default=None, help="deadline in seconds")
    args = parser.parse_args(argv)
    stub = connect(args.server)
    part = part_from_file(args.part)
    try:
        if args.command == "plan":
            request = service_pb2.PlanRequest(part=part, plan_options=plan_pb2.PlanOptions(mode=MODES[args.mode]))
            result = stub.Plan(request, timeout=args.timeout).plan
        else:
            result = stub.Analyze(service_pb2.AnalyzeRequest(part=part), timeout=args.timeout).analysis
    except grpc.RpcError as e:
        print("gvm_client: %s: %s (%s)" % (args.part, e.details(), e.code().name), file=sys.stderr)
        return 1
    print(json_format.MessageToJson(result, including_default_value_fields=True))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
