#!/usr/bin/python3
"""Small corruptions of STEP files, and what `gvm analyze FILE --lvm-only` does with each.

    corrupt_step.py make OUT_DIR N STEP...      N corrupted files from the given ones (seeded)
    corrupt_step.py run GVM TIMEOUT FILE...     each analysed; a summary line per outcome

The corruptions: a few bytes changed, the file cut short, a number replaced by 1e308 or
1e-320, an entity reference pointing elsewhere. The same seed gives the same files.
Outcomes: ok (exit 0), refused (exit 1, with a message), crashed (killed by a signal, or
an exit status over 1), timeout (over TIMEOUT seconds).
"""
import os
import random
import re
import subprocess
import sys

NUMBER = re.compile(rb"(?<![#\w.])-?\d+\.\d*(?:E[+-]?\d+)?")
REFERENCE = re.compile(rb"#(\d+)")


def bytes_changed(data, rng):
    b = bytearray(data)
    for _ in range(rng.randint(1, 4)):
        b[rng.randrange(len(b))] = rng.randrange(256)
    return bytes(b)


def cut_short(data, rng):
    return data[:rng.randrange(len(data) // 4, len(data))]


def extreme_number(data, rng):
    matches = list(NUMBER.finditer(data))
    out = data
    for m in sorted(rng.sample(matches, min(len(matches), rng.randint(1, 3))), key=lambda m: -m.start()):
        out = out[:m.start()] + rng.choice([b"1.E308", b"-1.E308", b"1.E-320", b"0."]) + out[m.end():]
    return out


def reference_moved(data, rng):
    matches = [m for m in REFERENCE.finditer(data) if data[m.end():m.end() + 1] != b"="
               and data[max(0, m.start() - 1):m.start()] != b"\n"]
    ids = [m.group(1) for m in REFERENCE.finditer(data)]
    out = data
    for m in sorted(rng.sample(matches, min(len(matches), rng.randint(1, 3))), key=lambda m: -m.start()):
        out = out[:m.start(1)] + rng.choice(ids) + out[m.end(1):]
    return out


KINDS = [("bytes", bytes_changed), ("cut", cut_short), ("number", extreme_number), ("ref", reference_moved)]


def make(out_dir, n, sources):
    os.makedirs(out_dir, exist_ok=True)
    rng = random.Random(20261207)
    for i in range(n):
        src = sources[i % len(sources)]
        name, corrupt = KINDS[(i // len(sources)) % len(KINDS)]
        with open(src, "rb") as f:
            data = corrupt(f.read(), rng)
        base = os.path.splitext(os.path.basename(src))[0]
        with open(os.path.join(out_dir, f"{i:03d}-{name}-{base}.stp"), "wb") as f:
            f.write(data)


def outcome(gvm, timeout, path):
    try:
        run = subprocess.run([gvm, "analyze", path, "--lvm-only", "-q", "--json", os.devnull],
                             capture_output=True, text=True, timeout=timeout)
    except subprocess.TimeoutExpired:
        return "timeout", ""
    message = (run.stderr.strip().splitlines() or [""])[-1]
    if run.returncode == 0:
        return "ok", ""
    if run.returncode == 1 and message:
        return "refused", message
    return "crashed", f"exit {run.returncode}: {message}"


def main(argv):
    if len(argv) >= 5 and argv[1] == "make":
        make(argv[2], int(argv[3]), argv[4:])
        return 0
    if len(argv) >= 5 and argv[1] == "run":
        gvm, timeout = argv[2], float(argv[3])
        counts = {}
        for path in argv[4:]:
            kind, message = outcome(gvm, timeout, path)
            counts[kind] = counts.get(kind, 0) + 1
            print(f"{kind:8} {os.path.basename(path)} {message[:200]}")
        print("summary: " + ", ".join(f"{k} {v}" for k, v in sorted(counts.items())))
        return 0
    print(__doc__, file=sys.stderr)
    return 2


if __name__ == "__main__":
    sys.exit(main(sys.argv))
