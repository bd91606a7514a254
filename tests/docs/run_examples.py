#!/usr/bin/python3
# SPDX-License-Identifier: BSD-3-Clause
"""Runs the bandlight command examples of README.md and docs/*.md and compares
what they print and write with a committed golden manifest.

    run_examples.py --bandlight BUILD/bandlight --out DIR [--golden tests/docs/golden.json]
    run_examples.py --bandlight BUILD/bandlight --out DIR --write-golden tests/docs/golden.json
    run_examples.py --list

What runs. Every line of a ```sh, ```bash, ```shell or ```console block of README.md
and docs/*.md (in that order, pages sorted by name) that invokes `bandlight`
(`./build/bandlight ...`, `bandlight ...`, or `$ ./build/bandlight ...` in a block
that shows a terminal transcript: there only `$ ` lines are commands, the rest is output).
Lines ending in a backslash are joined; comments are dropped; a line that chains
commands with `&&`, `;` or `||` contributes its bandlight commands only (the
set-up line's install and cmake steps are not run). Other programs (oiiotool,
ociocheck, python3, cmake) are not run. A bandlight command that needs a shell
(a pipe or a redirection) and the commands of the SKIP table are listed as
skipped, with the reason, in the manifest.

How it runs. Each block starts in a fresh scratch folder DIR/work holding the
inputs the examples take for granted (below); its commands run there in order,
so a command may read what an earlier one of the same block wrote. The
command's program is replaced by --bandlight, no shell is involved, the
environment is LC_ALL=C, TZ=UTC, HOME=DIR/home and PATH (and the sanitisers'
options, leak check off, when set), and each command has
a timeout (--timeout, default 300 s). What each printed is kept in
DIR/logs/NNN.stdout and NNN.stderr (normalised, as hashed).

Inputs, written deterministically into every scratch folder: plate.exr and
plate.1001.exr ... plate.1003.exr (64x32 float RGBA, uncompressed EXR written by
this script), surfaces.csv (six of rawtoaces' 190 training remittances from
data/ref/rawtoaces_190.csv), camera.csv (the CIE 1931 observer from data/cmf as
a camera's R, G, B sensitivities), arri_d21.json (rawtoaces' ARRI D21
sensitivities, tests/data/rawtoaces), scenes/ (the bundled scenes) and
docs/examples/ (the example inputs the docs name by that path: docs/wall.md's
emitter spectra).

The manifest (DIR/manifest.json) holds for each command, keyed by its text (a
command that occurs again gets " #2", " #3"), its exit code, the sha256 of its
stdout and stderr, and the sha256 of every file it created or changed in the
scratch folder (path relative to it; "deleted" for a file it removed), after
normalisation:
  - the scratch folder's absolute path becomes <DIR> and the program's path
    <BANDLIGHT>, in output and in text files;
  - timings are masked (the number and the padding before it): a number
    followed by ms, s, ns, us, µs, ns/pixel or Mpixel/s, the last column of a
    table whose header ends in ns/pixel, and the values of the ns_per_pixel, mpixel_per_s and seconds fields of JSON
    (printed or written to a .json file; the file must parse as JSON);
  - image files (.exr, .png, .tif, .tiff) are hashed as raw bytes, except the
    time stamp OpenImageIO writes into them (the EXR capDate attribute, a TIFF
    DateTime), which is zeroed.
The golden is such a manifest; it holds no absolute paths. --golden compares:
every difference is printed and the exit code is 1, 0 when all agree.
--partial compares only the commands the docs read here contain (for the docs
of an older tree, e.g. --source OTHER_TREE).
"""

import argparse
import hashlib
import json
import os
import re
import shlex
import shutil
import struct
import subprocess
import sys
import time
from pathlib import Path

SOURCE_DIR = Path(__file__).resolve().parents[2]

# Commands that are not run, by their text, with the reason.
SKIP = {
    # e.g. "./build/bandlight accuracy --plot docs/accuracy.png": "the full report takes 11.5 minutes",
}

FENCE = re.compile(r"^\s*(```+|~~~+)\s*([A-Za-z0-9_+-]*)")
SHELL_LANGS = {"sh", "bash", "shell", "console"}
ENV_ASSIGNMENT = re.compile(r"^[A-Za-z_][A-Za-z0-9_]*=")
CHAIN = {"&&", ";", "||"}
IMAGE_SUFFIXES = {".exr", ".png", ".tif", ".tiff"}
TIMING_FIELDS = ("ns_per_pixel", "mpixel_per_s", "seconds")
NUMBER = r"[-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?"
TIMING = re.compile(r"([ \t]*)(?<![\w.])" + NUMBER + r"(\s*)(ns/pixel|Mpixel/s|ms|µs|us|ns|s)(?![\w/])")
JSON_TIMING = re.compile(r'("(?:' + "|".join(TIMING_FIELDS) + r')"\s*:\s*)' + NUMBER)
LAST_NUMBER = re.compile(r"([ \t]*)(?<![\w.])" + NUMBER + r"(\s*)$")
MASK = "<T>"


# ---------------------------------------------------------------- extraction

def doc_pages(root):
    pages = [root / "README.md"] + sorted((root / "docs").glob("*.md"))
    return [p for p in pages if p.is_file()]


def shell_blocks(text):
    """Yields (first line number, lines) of each shell code block."""
    lines = text.split("\n")
    i = 0
    while i < len(lines):
        m = FENCE.match(lines[i])
        if not m:
            i += 1
            continue
        fence, lang, start = m.group(1), m.group(2).lower(), i + 1
        i += 1
        body = []
        while i < len(lines) and not lines[i].strip().startswith(fence):
            body.append(lines[i])
            i += 1
        i += 1
        if lang in SHELL_LANGS:
            yield start + 1, lang, body


def logical_lines(first, lang, body):
    """Yields (line number, text) of each command line of a block, joined over
    backslash continuations; in a transcript block only the `$ ` lines."""
    transcript = lang == "console" or any(l.lstrip().startswith("$ ") for l in body)
    i = 0
    while i < len(body):
        line, number = body[i].strip(), first + i
        i += 1
        if transcript:
            if not line.startswith("$ "):
                continue
            line = line[2:].strip()
        if not line or line.startswith("#"):
            continue
        while line.endswith("\\") and i < len(body):
            line = line[:-1].rstrip() + " " + body[i].strip()
            i += 1
        yield number, line


def tokens(line):
    lexer = shlex.shlex(line, posix=True, punctuation_chars=True)
    lexer.whitespace_split = True
    lexer.commenters = ""
    out = []
    for t in lexer:
        if t.startswith("#"):
            break  # a trailing comment
        out.append(t)
    return out


def join(words):
    safe = re.compile(r"^[^\s'\"\\$`;&|<>()*?\[\]{}!]+$")
    return " ".join(w if safe.match(w) else shlex.quote(w) for w in words)


def is_bandlight(word):
    return Path(word).name == "bandlight"


def extract(root):
    """Returns the blocks, each a list of commands:
    {"key", "where", "env", "argv", "skip"}."""
    blocks, seen = [], {}
    for page in doc_pages(root):
        rel = page.relative_to(root).as_posix()
        for first, lang, body in shell_blocks(page.read_text(encoding="utf-8")):
            commands = []
            for number, line in logical_lines(first, lang, body):
                words = tokens(line)
                segments, current = [], []
                for w in words:
                    if w in CHAIN:
                        segments.append(current)
                        current = []
                    else:
                        current.append(w)
                segments.append(current)
                for seg in segments:
                    env, k = {}, 0
                    while k < len(seg) and ENV_ASSIGNMENT.match(seg[k]):
                        name, value = seg[k].split("=", 1)
                        env[name] = value
                        k += 1
                    if k >= len(seg) or not is_bandlight(seg[k]):
                        continue
                    text = join(seg)
                    n = seen.get(text, 0) + 1
                    seen[text] = n
                    key = text if n == 1 else f"{text} #{n}"
                    skip = SKIP.get(text)
                    shell = [w for w in seg if w and set(w) <= set("|&<>()")]
                    if skip is None and shell:
                        skip = f"needs a shell ({' '.join(shell)})"
                    commands.append({"key": key, "where": f"{rel}:{number}", "env": env,
                                     "argv": seg[k + 1:], "skip": skip})
            if commands:
                blocks.append(commands)
    return blocks


# -------------------------------------------------------------------- inputs

def write_exr(path, width, height, pixel):
    """An uncompressed scanline float RGBA OpenEXR file; pixel(x, y) -> (r, g, b, a)."""
    def attr(name, kind, data):
        return name.encode() + b"\0" + kind.encode() + b"\0" + struct.pack("<i", len(data)) + data
    channels = b"".join(c.encode() + b"\0" + struct.pack("<iBBBBii", 2, 0, 0, 0, 0, 1, 1)
                        for c in "ABGR") + b"\0"
    box = struct.pack("<iiii", 0, 0, width - 1, height - 1)
    header = (struct.pack("<ii", 20000630, 2) +
              attr("capDate", "string", b"2024:01:01 00:00:00") +
              attr("channels", "chlist", channels) +
              attr("compression", "compression", b"\0") +
              attr("dataWindow", "box2i", box) +
              attr("displayWindow", "box2i", box) +
              attr("lineOrder", "lineOrder", b"\0") +
              attr("pixelAspectRatio", "float", struct.pack("<f", 1.0)) +
              attr("screenWindowCenter", "v2f", struct.pack("<ff", 0.0, 0.0)) +
              attr("screenWindowWidth", "float", struct.pack("<f", 1.0)) + b"\0")
    line_bytes = width * 4 * 4
    table_end = len(header) + 8 * height
    offsets = b"".join(struct.pack("<Q", table_end + y * (8 + line_bytes)) for y in range(height))
    lines = []
    for y in range(height):
        px = [pixel(x, y) for x in range(width)]
        data = b"".join(struct.pack(f"<{width}f", *(p[c] for p in px)) for c in (3, 2, 1, 0))
        lines.append(struct.pack("<ii", y, len(data)) + data)
    path.write_bytes(header + offsets + b"".join(lines))


def data_rows(path):
    return [l for l in path.read_text().splitlines() if l.strip() and not l.startswith("#")]


def make_inputs(root, folder):
    folder.mkdir(parents=True)
    for frame, name in ((0, "plate.exr"), (1001, "plate.1001.exr"), (1002, "plate.1002.exr"),
                        (1003, "plate.1003.exr")):
        k = 1.0 + (frame % 1000) / 4.0
        write_exr(folder / name, 64, 32, lambda x, y, k=k: (
            k * (x + 1) / 64.0, k * (y + 1) / 32.0, k * ((x + y) % 7 + 1) / 8.0, 1.0))
    rows = data_rows(root / "data" / "ref" / "rawtoaces_190.csv")
    (folder / "surfaces.csv").write_text(
        "# Six of rawtoaces' 190 training remittances (data/ref/rawtoaces_190.csv)\n" +
        "".join(",".join(r.split(",")[:7]) + "\n" for r in rows))
    rows = data_rows(root / "data" / "cmf" / "cie1931_2deg_xyz.csv")
    (folder / "camera.csv").write_text(
        "# The CIE 1931 observer as a camera (data/cmf/cie1931_2deg_xyz.csv)\nwavelength,R,G,B\n" +
        "".join(r + "\n" for r in rows[1:]))
    shutil.copyfile(root / "tests" / "data" / "rawtoaces" / "arri_d21_380_780_5.json",
                    folder / "arri_d21.json")
    shutil.copytree(root / "scenes", folder / "scenes")
    shutil.copytree(root / "docs" / "examples", folder / "docs" / "examples")


# ------------------------------------------------------------- normalisation

class Normaliser:
    def __init__(self, work, program):
        self.paths = []
        for p, token in ((work, "<DIR>"), (program, "<BANDLIGHT>")):
            for form in {str(p), os.path.realpath(p), os.path.abspath(p)}:
                self.paths.append((form, token))
        self.paths.sort(key=lambda x: -len(x[0]))

    def text(self, s):
        for form, token in self.paths:
            s = s.replace(form, token)
        s = JSON_TIMING.sub(lambda m: m.group(1) + '"' + MASK + '"', s)
        # The number and the padding before it, which depends on its width.
        s = TIMING.sub(lambda m: (" " if m.group(1) else "") + MASK + m.group(2) + m.group(3), s)
        out, in_cost_table = [], False
        for line in s.split("\n"):
            if not line.strip():
                in_cost_table = False
            elif in_cost_table:
                line = LAST_NUMBER.sub(lambda m: (" " if m.group(1) else "") + MASK + m.group(2), line)
            if line.rstrip().endswith("ns/pixel"):
                in_cost_table = True
            out.append(line)
        return "\n".join(out)

    def output(self, data):
        return self.text(data.decode("utf-8", "surrogateescape")).encode("utf-8", "surrogateescape")

    def file(self, path):
        data = path.read_bytes()
        suffix = path.suffix.lower()
        if suffix in IMAGE_SUFFIXES:
            data = re.sub(rb"(capDate\0string\0\x13\0\0\0)[^\0]{19}",
                          lambda m: m.group(1) + b"0" * 19, data)
            if suffix in (".tif", ".tiff"):
                data = re.sub(rb"\d{4}:\d\d:\d\d \d\d:\d\d:\d\d", b"0000:00:00 00:00:00", data)
            return data
        if suffix == ".json":
            json.loads(data)  # an invalid JSON file is an error, not a hash
        try:
            return self.text(data.decode("utf-8")).encode("utf-8")
        except UnicodeDecodeError:
            return data


def sha(data):
    return hashlib.sha256(data).hexdigest()


def snapshot(folder):
    state = {}
    for dirpath, _, files in os.walk(folder):
        for f in files:
            p = Path(dirpath) / f
            st = p.lstat()
            state[p.relative_to(folder).as_posix()] = (st.st_ino, st.st_size, st.st_mtime_ns)
    return state


# ------------------------------------------------------------------- running

def run(args):
    program = Path(args.bandlight).resolve()
    if not os.access(program, os.X_OK):
        sys.exit(f"run_examples: {args.bandlight}: not an executable")
    out = Path(args.out).resolve()
    root = Path(args.source).resolve()
    blocks = extract(root)
    for sub in ("work", "inputs", "logs", "home"):
        shutil.rmtree(out / sub, ignore_errors=True)
    out.mkdir(parents=True, exist_ok=True)
    (out / "home").mkdir()
    (out / "logs").mkdir()
    make_inputs(root, out / "inputs")
    work = out / "work"
    norm = Normaliser(work, program)
    env = {"LC_ALL": "C", "TZ": "UTC", "HOME": str(out / "home"),
           "PATH": os.environ.get("PATH", "/usr/bin:/bin")}
    # Under the sanitised suite the commands keep ASan and UBSan but skip
    # LeakSanitizer's exit-time check, as every command a test runs does
    # (tests/cli/RunCommand.h): its tracer fails now and then while
    # OpenImageIO's workers or a gnuplot child are alive.
    for name in ("ASAN_OPTIONS", "UBSAN_OPTIONS", "LSAN_OPTIONS"):
        if name in os.environ:
            env[name] = os.environ[name]
    if "ASAN_OPTIONS" in env:
        env["ASAN_OPTIONS"] += ":detect_leaks=0"
    manifest = {
        "format": 1,
        "inputs": {k: sha(norm.file(out / "inputs" / k)) for k in sorted(snapshot(out / "inputs"))},
        "commands": {},
        "skipped": {},
    }
    total = sum(len(b) for b in blocks)
    n, failures, started = 0, [], time.monotonic()
    for block in blocks:
        shutil.rmtree(work, ignore_errors=True)
        shutil.copytree(out / "inputs", work)
        for cmd in block:
            n += 1
            key = cmd["key"]
            if cmd["skip"]:
                manifest["skipped"][key] = {"where": cmd["where"], "reason": cmd["skip"]}
                print(f"[{n}/{total}] skipped: {key} ({cmd['skip']})", file=sys.stderr)
                continue
            before = snapshot(work)
            t0 = time.monotonic()
            try:
                p = subprocess.run([str(program)] + cmd["argv"], cwd=work, env={**env, **cmd["env"]},
                                   stdin=subprocess.DEVNULL, capture_output=True,
                                   timeout=args.timeout)
                code, stdout, stderr = p.returncode, p.stdout, p.stderr
            except subprocess.TimeoutExpired as e:
                code, stdout, stderr = f"timeout after {args.timeout} s", e.stdout or b"", e.stderr or b""
            seconds = time.monotonic() - t0
            after = snapshot(work)
            files = {}
            for rel in sorted(set(before) | set(after)):
                if rel not in after:
                    files[rel] = "deleted"
                elif before.get(rel) != after[rel]:
                    files[rel] = sha(norm.file(work / rel))
            stdout, stderr = norm.output(stdout), norm.output(stderr)
            log = out / "logs" / f"{n:03d}"
            Path(f"{log}.stdout").write_bytes(stdout)
            Path(f"{log}.stderr").write_bytes(stderr)
            manifest["commands"][key] = {"where": cmd["where"], "exit": code, "stdout": sha(stdout),
                                         "stderr": sha(stderr), "files": files}
            status = "ok" if code == 0 else f"EXIT {code}"
            print(f"[{n}/{total}] {status} {seconds:.1f} s: {key}", file=sys.stderr)
            if code != 0:
                failures.append((key, cmd["where"], code, stderr.decode("utf-8", "replace").strip()))
    (out / "manifest.json").write_text(json.dumps(manifest, indent=1, ensure_ascii=False) + "\n")
    print(f"run_examples: {len(manifest['commands'])} commands run, {len(manifest['skipped'])} skipped,"
          f" {time.monotonic() - started:.0f} s; manifest in {out / 'manifest.json'}", file=sys.stderr)
    for key, where, code, err in failures:
        print(f"run_examples: {where}: `{key}` exited with {code}: {err.splitlines()[-1] if err else ''}",
              file=sys.stderr)
    return manifest, out


# ---------------------------------------------------------------- comparison

def compare(manifest, golden, partial, out):
    diffs = []
    if manifest.get("format") != golden.get("format"):
        diffs.append(f"manifest format {manifest.get('format')} against the golden's {golden.get('format')}")
    for name in sorted(set(manifest["inputs"]) | set(golden["inputs"])):
        if manifest["inputs"].get(name) != golden["inputs"].get(name):
            diffs.append(f"input {name}: {manifest['inputs'].get(name, 'missing')} against the golden's "
                         f"{golden['inputs'].get(name, 'missing')}")
    mine, theirs = manifest["commands"], golden["commands"]
    logs = {key: i for i, key in enumerate(mine, 1)}
    keys = list(mine) + [k for k in theirs if k not in mine]
    for key in keys:
        if key not in theirs:
            diffs.append(f"`{key}` ({mine[key]['where']}): not in the golden")
            continue
        if key not in mine:
            if not partial and key not in manifest["skipped"]:
                diffs.append(f"`{key}` ({theirs[key]['where']} in the golden): not in the docs any more")
            elif not partial:
                diffs.append(f"`{key}`: skipped here, run in the golden")
            continue
        a, b = mine[key], theirs[key]
        where = f"`{key}` ({a['where']})"
        if a["exit"] != b["exit"]:
            diffs.append(f"{where}: exit code {a['exit']}, golden {b['exit']}")
        for stream in ("stdout", "stderr"):
            if a[stream] != b[stream]:
                log = out / "logs" / f"{logs[key]:03d}.{stream}"
                diffs.append(f"{where}: {stream} differs (normalised text in {log})")
        for rel in sorted(set(a["files"]) | set(b["files"])):
            x, y = a["files"].get(rel), b["files"].get(rel)
            if x == y:
                continue
            if y is None:
                diffs.append(f"{where}: writes {rel}, the golden does not")
            elif x is None:
                diffs.append(f"{where}: does not write {rel}, the golden does")
            else:
                diffs.append(f"{where}: {rel} differs ({x[:12]} against the golden's {y[:12]})")
    return diffs


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0],
                                     formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--bandlight", help="the bandlight executable to run")
    parser.add_argument("--out", help="folder for the scratch folder, logs and manifest.json")
    parser.add_argument("--source", default=str(SOURCE_DIR),
                        help="source tree whose README.md and docs/*.md are read (default: this one)")
    parser.add_argument("--golden", help="compare the manifest with this golden manifest")
    parser.add_argument("--write-golden", metavar="FILE", help="write the manifest as the golden")
    parser.add_argument("--partial", action="store_true",
                        help="with --golden: golden commands the docs do not hold are no difference")
    parser.add_argument("--timeout", type=float, default=300.0, help="seconds per command (300)")
    parser.add_argument("--list", action="store_true", help="print the commands found and exit")
    args = parser.parse_args()
    if args.list:
        for block in extract(Path(args.source).resolve()):
            for cmd in block:
                print(f"{cmd['where']}: {cmd['key']}" + (f"   [skipped: {cmd['skip']}]" if cmd["skip"] else ""))
            print()
        return 0
    if not args.bandlight or not args.out:
        parser.error("--bandlight and --out are required")
    manifest, out = run(args)
    if args.write_golden:
        Path(args.write_golden).write_text(json.dumps(manifest, indent=1, ensure_ascii=False) + "\n")
        print(f"run_examples: wrote {args.write_golden}", file=sys.stderr)
    if args.golden:
        golden = json.loads(Path(args.golden).read_text())
        diffs = compare(manifest, golden, args.partial, out)
        for d in diffs:
            print(d)
        print(f"run_examples: {len(diffs)} difference(s) from {args.golden}", file=sys.stderr)
        return 1 if diffs else 0
    return 0


if __name__ == "__main__":
    sys.exit(main())
