#!/usr/bin/python3
# SPDX-License-Identifier: BSD-3-Clause
"""The figures the docs quote from bandlight's own output, made by bandlight.

    doc_tables.py --bandlight BUILD/bandlight --lut-accuracy BUILD/bench/lut_accuracy --check
    doc_tables.py --bandlight BUILD/bandlight --lut-accuracy BUILD/bench/lut_accuracy --write

A page marks each such passage:

    <!-- generated: NAME (tests/docs/doc_tables.py) -->
    ...
    <!-- end generated: NAME -->

and this script holds, for each NAME, the commands that give its figures
(their --json output) and how the passage is written from them, saying the
plates and options the figures were made with. --check runs them and fails
(exit 1, with a diff) when a page says anything else; --write rewrites the
passages. The test suite runs --check, so a figure in the docs is the figure
the tool gives.
"""

import argparse
import difflib
import json
import os
import re
import subprocess
import sys
import tempfile
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
MARK = re.compile(r"<!-- generated: (?P<name>[a-z0-9-]+) \(tests/docs/doc_tables.py\) -->\n"
                  r"(?P<body>.*?)"
                  r"<!-- end generated: (?P=name) -->", re.S)


def run(args, cwd):
    env = {"LC_ALL": "C", "TZ": "UTC", "PATH": os.environ.get("PATH", "/usr/bin:/bin"),
           "HOME": str(cwd)}
    for key in ("ASAN_OPTIONS", "UBSAN_OPTIONS", "LSAN_OPTIONS"):
        if key in os.environ:
            env[key] = os.environ[key]
    if "ASAN_OPTIONS" in env:
        env["ASAN_OPTIONS"] += ":detect_leaks=0"
    p = subprocess.run([str(a) for a in args], cwd=cwd, capture_output=True, text=True, env=env,
                       timeout=600)
    if p.returncode != 0:
        sys.exit(f"doc_tables.py: {' '.join(map(str, args))} failed ({p.returncode}):\n"
                 f"{p.stderr}")
    return p.stdout


def lut_accuracy(tools, work):
    rows = json.loads(run([tools.lut_accuracy, "--json"], work))["rows"]
    lines = ["Made by `./build/bench/lut_accuracy` (looks to D65 in ACEScg, the log2 "
             "shaper; `--json` gives every size): relative error per pixel against the "
             "exact transform, for both plate conventions. A balanced look is not the lit "
             "one (a balanced band3 look is not neutral, see [Plates](plates.md)), and its "
             "LUT errs differently.",
             "",
             "| transform | plates | size | greys, max | colours, median | p95 | max |",
             "|---|---|---|---|---|---|---|"]
    for r in rows:
        if r["size"] not in (33, 65):
            continue
        lines.append(f"| {r['method']} {r['from']}→{r['to']} | {r['plates']} | {r['size']} | "
                     f"{r['grey_max']:.1e} | {r['median']:.1e} | {r['p95']:.1e} | "
                     f"{r['max']:.1e} |")
    return "\n".join(lines) + "\n"


def shot_rows(tools, work):
    bl = tools.bandlight
    run([bl, "render", ROOT / "scenes" / "tcs_spectral_F11.yaml", "--spectra", "-o",
         "shot.exr"], work)
    doc = json.loads(run([bl, "accuracy", "--image", "shot.exr", "--from", "F11", "--to",
                          "D65", "--methods", "none,bradford,rootpoly", "--ideal-only",
                          "--no-cost", "--plates", "both", "--heatmaps", "maps", "--json",
                          "-"], work))

    def mean(method, plates, rows="rows"):
        found = [r["mean"] for r in doc[rows] if r["set"] == "shot.exr" and
                 r["method"] == method and r["plates"] in (plates, plates + "-cat02") and
                 r["exposure"] == 1.0 and r["from"] == "F11"]
        assert len(found) == 1, (method, plates, found)
        return found[0]

    lines = ["Made with the commands above and `--plates both --json -` (F11 → D65, ideal "
             "forms, the shot's pixels at exposure 1), mean ΔE00:",
             "",
             "| method | lit plates | balanced plates |",
             "|---|---|---|"]
    for m in ("none", "bradford", "rootpoly"):
        lines.append(f"| {m} | {mean(m, 'lit'):.2f} | {mean(m, 'balanced'):.2f} |")
    lines.append(f"| floor: any root polynomial fitted on the shot itself | "
                 f"{mean('floor-rootpoly', 'lit', 'floor'):.2f} | |")
    maps = {h["method"]: h for h in doc["heatmaps"]}
    lines += ["",
              "On lit plates doing nothing is by far the worst; on balanced plates the balance has "
              "already done most of the work, and doing nothing "
              + ("beats" if mean("none", "balanced") < mean("bradford", "balanced")
                 else "loses to")
              + " Bradford. The heat maps (balanced plates, the default) peak at "
              + ", ".join(f"{m} {maps[m]['max']:.1f}" for m in ("none", "bradford", "rootpoly"))
              + " ΔE00."]
    return "\n".join(lines) + "\n"


def cri_json(tools, work):
    out = run([tools.bandlight, "cri", "--illuminant", "F11", "--json"], work)
    return ("```console\n$ ./build/bandlight cri --illuminant F11 --json\n" + out +
            ("" if out.endswith("\n") else "\n") + "```\n")


BUILTIN_LIGHTS = ["A", "planck:3200", "D50", "daylight:5600", "D65", "C"] + \
    [f"F{i}" for i in range(1, 13)]


def quality_builtin(tools, work):
    doc = json.loads(run([tools.bandlight, "quality", *BUILTIN_LIGHTS, "--json"], work))

    def value(light, key, field, digits):
        score = light.get(key)
        v = score.get(field) if score else None
        return "–" if v is None else f"{v:.{digits}f}"

    lines = ["Made by `./build/bandlight quality " + " ".join(BUILTIN_LIGHTS) + " --json` "
             "(every score against its own default reference; Rf as the CIE 224 calculator computes "
             "it, Rg as the TM-30 calculator does):",
             "",
             "| light | CCT (K) | Duv | Ra | R9 | Rf | Rg | SSI | TLCI Qa |",
             "|---|---|---|---|---|---|---|---|---|"]
    for light in doc:
        r9 = light["cri"]["R"][8] if light.get("cri") else None
        lines.append(
            f"| {light['light']} | {light['cct']:.0f} | {round(light['duv'], 4) + 0.0:.4f} | "
            f"{value(light, 'cri', 'Ra', 0)} | {'–' if r9 is None else f'{r9:.0f}'} | "
            f"{value(light, 'cie2017', 'Rf', 0)} | {value(light, 'tm30', 'Rg', 0)} | "
            f"{value(light, 'ssi', 'value', 0)} | {value(light, 'tlci', 'Qa', 0)} |")
    return "\n".join(lines) + "\n"


def wall_figures(tools, work):
    camera = ROOT / "tests" / "data" / "rawtoaces" / "arri_d21_380_780_5.json"
    emitters = {n: ROOT / "docs" / "examples" / "wall" / f for n, f in
                (("R", "red.csv"), ("G", "green.csv"), ("B", "blue.csv"), ("W", "white.csv"))}
    walls = {}
    for wall in ("RGB", "RGBW"):
        args = [tools.bandlight, "wall", "--emitter",
                *[f"{n}={emitters[n]}" for n in wall], "--camera", camera,
                "--white-balance", "5600K", "3200K", "--content-space", "rec709",
                "--out", work / wall.lower(), "--json"]
        walls[wall] = json.loads(run(args, work))

    def stat(s):
        return f"{s['mean']:.2f} ({s['p95']:.2f})"

    lines = ["Made by the two commands above with `--json` (report.json's figures).",
             "",
             "In the frustum:",
             "",
             "| wall | white balance | solution | condition number | residual | "
             "corners needing a negative drive |",
             "|---|---|---|---|---|---|"]
    for wall, doc in walls.items():
        for b in doc["white_balances"]:
            f = b["in_frustum"]
            negative = [c["name"] for c in f["corners"] if c["negative"]]
            lines.append(f"| {wall} | {b['key']} | {f['solution']} | "
                         f"{f['condition_number']:.2f} | {f['residual']:.1e} | "
                         f"{len(negative)} of {len(f['corners'])}"
                         + (f" ({', '.join(negative)})" if negative else "") + " |")
    lines += ["",
              "Out of the frustum, the wall showing its white balance's light, ΔE00 mean "
              "(p95) on each set (the test set is fitted on by nothing):",
              "",
              "| wall | white balance = shows | set | before | pre-corrected | "
              "post-camera 3×3 |",
              "|---|---|---|---|---|---|"]
    for wall, doc in walls.items():
        for b in doc["white_balances"]:
            for shown in b["out_of_frustum"]:
                if shown["shows"] != b["light"]:
                    continue
                # A drive with a channel below zero is no light a wall can
                # emit: its column is marked.
                def mark(drive):
                    scale = max(abs(v) for v in drive)
                    return " (negative drive)" if any(v < -1e-9 * scale for v in drive) else ""
                plain = mark(shown["drive"])
                pre = mark(shown["pre_corrected_drive"])
                for name, e in shown["errors"].items():
                    lines.append(f"| {wall} | {b['key']} | {name} | {stat(e['before'])}{plain} | "
                                 f"{stat(e['pre_corrected'])}{pre} | "
                                 f"{stat(e['post_corrected'])}{plain} |")
    lines += ["",
              "The corrections against the plain least-squares fit of their form, mean ΔE00 "
              "on the data they were fitted on:",
              "",
              "| wall | white balance | pre-correction: before → bandlight's (plain LS) | "
              "post-camera 3×3: before → bandlight's (plain LS) | root polynomial (plain LS) | "
              "registry's rootpoly-camera |",
              "|---|---|---|---|---|---|"]
    for wall, doc in walls.items():
        for b in doc["white_balances"]:
            pre, post = b["pre_correction"], b["post_camera"]
            root = post["root_polynomial"]
            lines.append(f"| {wall} | {b['key']} | {pre['before']['mean']:.2f} → "
                         f"{pre['after']['mean']:.2f} ({pre['least_squares']['mean']:.2f}) | "
                         f"{post['before']['mean']:.2f} → {post['after']['mean']:.2f} "
                         f"({post['least_squares']['mean']:.2f}) | {root['after']['mean']:.2f} "
                         f"({root['least_squares']['mean']:.2f}) | "
                         f"{post['registry_rootpoly_camera']['mean']:.2f} |")

    def headline(q):
        if q is None:
            return "– (negative drive)"
        r9 = q["cri"]["R"][8] if q.get("cri") else None
        parts = [f"Ra {q['cri']['Ra']:.0f}" if q.get("cri") else None,
                 f"R9 {r9:.0f}" if r9 is not None else None,
                 f"Rf {q['cie2017']['Rf']:.0f}" if q.get("cie2017") else None,
                 f"Rg {q['tm30']['Rg']:.0f}" if q.get("tm30") else None,
                 f"SSI {q['ssi']['value']:.0f}" if q.get("ssi") else None,
                 f"TLCI {q['tlci']['Qa']:.0f}" if q.get("tlci") else None]
        return ", ".join(p for p in parts if p)

    lines += ["",
              "The wall's light scored as `bandlight quality` scores a light:",
              "",
              "| wall | white balance | its white | showing the white balance's light | "
              "pre-corrected |",
              "|---|---|---|---|---|"]
    for wall, doc in walls.items():
        for b in doc["white_balances"]:
            shown = next(x for x in b["out_of_frustum"] if x["shows"] == b["light"])
            lines.append(f"| {wall} | {b['key']} | {headline(b['white_scores'])} | "
                         f"{headline(shown['scores'])} | "
                         f"{headline(shown['pre_corrected_scores'])} |")
    return "\n".join(lines) + "\n"


GENERATORS = {"wall-figures": wall_figures, "lut-accuracy": lut_accuracy, "shot-rows": shot_rows, "cri-json": cri_json,
              "quality-builtin": quality_builtin}


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--bandlight", required=True)
    ap.add_argument("--lut-accuracy", required=True)
    mode = ap.add_mutually_exclusive_group(required=True)
    mode.add_argument("--check", action="store_true")
    mode.add_argument("--write", action="store_true")
    tools = ap.parse_args()
    tools.bandlight = Path(tools.bandlight).resolve()
    tools.lut_accuracy = Path(tools.lut_accuracy).resolve()
    pages = [ROOT / "README.md"] + sorted((ROOT / "docs").glob("*.md"))
    seen, differ = set(), False
    with tempfile.TemporaryDirectory(prefix="bandlight-doc-tables-") as scratch:
        for page in pages:
            text = page.read_text()

            def fill(m):
                name = m.group("name")
                if name not in GENERATORS:
                    sys.exit(f"doc_tables.py: {page}: unknown generated passage '{name}'")
                seen.add(name)
                work = Path(scratch) / name
                work.mkdir(exist_ok=True)
                body = GENERATORS[name](tools, work)
                return m.group(0).replace(m.group("body"), body, 1) if m.group("body") else \
                    m.group(0).replace("-->\n<!-- end", "-->\n" + body + "<!-- end", 1)

            new = MARK.sub(fill, text)
            if new != text:
                if tools.write:
                    page.write_text(new)
                    print(f"rewrote {page.relative_to(ROOT)}")
                else:
                    differ = True
                    sys.stdout.writelines(difflib.unified_diff(
                        text.splitlines(True), new.splitlines(True),
                        f"{page.relative_to(ROOT)} (as written)",
                        f"{page.relative_to(ROOT)} (as bandlight gives it)"))
    missing = set(GENERATORS) - seen
    if missing:
        sys.exit(f"doc_tables.py: no page holds the passages {sorted(missing)}")
    if differ:
        print("doc_tables.py: the docs quote other figures than bandlight gives; run with "
              "--write to rewrite them", file=sys.stderr)
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
