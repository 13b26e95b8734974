#!/usr/bin/python3
"""Runs the shell examples of the README and docs/ that are marked as tests, as a user
would type them, and fails when one fails.

    run_doc_examples.py --source DIR --build DIR [--path DIR ...] [--list] [FILE.md ...]

A marked example is a fenced block whose info string is `sh test`:

    ```sh test
    gvm plan tests/data/featuretype.off
    ```

`sh test exit=N` expects exit status N instead of 0 (a refused part, say).
It may be followed (blank lines between allowed) by a block tagged `text prints`: every
line of it other than `...` must appear in what the commands print (standard output and
error together), as a whole line, in that order; `...` stands for lines left out.

Each block runs with `bash -e -o pipefail` in a fresh temporary directory that holds a
symbolic link to every top-level entry of the source directory, except that its
`build/release` is the build under test (--build): so `tests/data/...`, `service/...` and
`build/release/...` resolve as in the checkout, and files the example writes land in the
temporary directory. The build's service/ directory (`gvm`, `gvmd`) and each --path are
first on PATH, and XDG_RUNTIME_DIR is a private directory of the block's own (gvmd's
default socket). Whatever a block leaves running is killed with it. Without FILEs: README.md, docs/*.md, benchmarks/README.md.
Exits 1 when a block fails or prints otherwise, or when README.md has no marked block.
"""
import argparse
import glob
import os
import re
import signal
import subprocess
import sys
import tempfile
import time

FENCE = re.compile(r"^(\s*)```(.*)$")
BLOCK_SECONDS = 180


def blocks(path):
    """(line, kind, text) of every fenced block of a Markdown file; kind is 'test', 'prints'
    or None."""
    out = []
    lines = open(path, encoding="utf-8").read().split("\n")
    i = 0
    while i < len(lines):
        m = FENCE.match(lines[i])
        if not m:
            i += 1
            continue
        indent, info = m.group(1), m.group(2).strip().split()
        start, body = i + 1, []
        i += 1
        while i < len(lines) and not re.match(r"^\s*```\s*$", lines[i]):
            line = lines[i]
            body.append(line[len(indent):] if line.startswith(indent) else line.lstrip())
            i += 1
        i += 1
        kind, status = None, 0
        if info[:2] == ["sh", "test"]:
            kind = "test"
            for word in info[2:]:
                if not re.fullmatch(r"exit=\d+", word):
                    raise SystemExit("%s:%d: unknown word '%s' after ```sh test" % (path, start, word))
                status = int(word[5:])
        elif info[:2] == ["text", "prints"]:
            kind = "prints"
        out.append((start, kind, "\n".join(body) + "\n", i, status))
    return out, lines


def examples(path):
    """(line, commands, exit status, expected lines or None) of the marked blocks of a file."""
    found, lines = blocks(path)
    result = []
    for k, (line, kind, text, end, status) in enumerate(found):
        if kind != "test":
            continue
        expected = None
        if k + 1 < len(found) and found[k + 1][1] == "prints":
            between = lines[end:found[k + 1][0] - 1]
            if all(not s.strip() for s in between):
                expected = [s.rstrip() for s in found[k + 1][2].split("\n") if s.strip()]
        result.append((line, text, status, expected))
    return result


def check_prints(expected, output):
    """The first expected line not found in order in the output, or None."""
    got = [s.rstrip() for s in output.split("\n")]
    at = 0
    for want in expected:
        if want.strip() == "...":
            continue
        while at < len(got) and got[at] != want:
            at += 1
        if at == len(got):
            return want
        at += 1
    return None


def farm(source, build, into):
    for name in os.listdir(source):
        if name.startswith(".") and name != ".ci":
            continue
        if name == "build":
            continue
        os.symlink(os.path.join(source, name), os.path.join(into, name))
    os.mkdir(os.path.join(into, "build"))
    os.symlink(build, os.path.join(into, "build", "release"))


def run_block(source, build, paths, commands):
    with tempfile.TemporaryDirectory(prefix="gvm-doc-") as tmp:
        work, runtime = os.path.join(tmp, "work"), os.path.join(tmp, "run")
        os.mkdir(work)
        os.mkdir(runtime, 0o700)
        farm(source, build, work)
        env = dict(os.environ)
        env["PATH"] = os.pathsep.join(paths + [env.get("PATH", "/usr/bin:/bin")])
        env["XDG_RUNTIME_DIR"] = runtime
        env["PWD"] = work
        env.pop("OLDPWD", None)
        env.pop("GVM_PYTHON_PATH", None)  # the client's default: build/release/python
        script = os.path.join(tmp, "example.sh")
        with open(script, "w") as f:
            f.write(commands)
        start = time.monotonic()
        # Output to a file, not a pipe: a process the block leaves running (a daemon started
        # with &) would hold a pipe open after the block ends.
        log_path = os.path.join(tmp, "output")
        with open(log_path, "w") as log:
            proc = subprocess.Popen(["bash", "--noprofile", "--norc", "-e", "-o", "pipefail", script], cwd=work,
                                    env=env, stdout=log, stderr=subprocess.STDOUT, start_new_session=True)
            try:
                code = proc.wait(timeout=BLOCK_SECONDS)
                note = ""
            except subprocess.TimeoutExpired:
                code, note = -signal.SIGKILL, "\n(killed after %d s)\n" % BLOCK_SECONDS
            finally:
                try:  # the block's session: whatever it left behind
                    os.killpg(proc.pid, signal.SIGKILL)
                except ProcessLookupError:
                    pass
                proc.wait()
        with open(log_path, errors="replace") as f:
            output = f.read() + note
        return code, output, time.monotonic() - start


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--source", required=True, help="the checkout (README.md, docs/, tests/data/)")
    parser.add_argument("--build", required=True, help="the build under test (its service/ and python/)")
    parser.add_argument("--path", action="append", default=[], help="another directory put first on PATH (repeatable)")
    parser.add_argument("--list", action="store_true", help="print the marked blocks, run nothing")
    parser.add_argument("files", nargs="*")
    args = parser.parse_args()
    source = os.path.abspath(args.source)
    files = args.files or ([os.path.join(source, "README.md")] + sorted(glob.glob(os.path.join(source, "docs", "*.md")))
                           + [os.path.join(source, "benchmarks", "README.md")])
    files = [f for f in files if os.path.exists(f)]
    build = os.path.abspath(args.build)
    paths = [os.path.join(build, "service")] + [os.path.abspath(p) for p in args.path]

    failures, count = [], 0
    readme_blocks = 0
    for path in files:
        rel = os.path.relpath(path, source)
        for line, commands, status, expected in examples(path):
            count += 1
            if os.path.basename(path) == "README.md" and os.path.dirname(os.path.abspath(path)) == source:
                readme_blocks += 1
            where = "%s:%d" % (rel, line)
            if args.list:
                print("== %s%s\n%s" % (where, " (with its output)" if expected else "", commands))
                continue
            code, output, seconds = run_block(source, build, paths, commands)
            problem = None
            if code != status:
                problem = "exit status %d, not %d" % (code, status)
            elif expected:
                missing = check_prints(expected, output)
                if missing is not None:
                    problem = "does not print (in this order) the line\n    %s" % missing
            print("%s %s (%.1f s)" % ("FAIL" if problem else "ok  ", where, seconds))
            if problem:
                print("--- commands\n%s--- output\n%s--- %s\n" % (commands, output, problem))
                failures.append(where)
    if not args.list:
        print("%d examples, %d failed%s" % (count, len(failures), (": " + ", ".join(failures)) if failures else ""))
    if readme_blocks == 0 and any(os.path.basename(f) == "README.md" for f in files):
        print("README.md has no block marked ```sh test")
        return 1
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
