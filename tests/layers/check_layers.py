#!/usr/bin/python3
# SPDX-License-Identifier: BSD-3-Clause
"""The tree's one structural rule: includes point down the layers only.

Headers are included by their path from the repository's root
("transforms/Methods.h"), so each include names a file of the checkout; one
that does not (a path that would resolve only in a build tree) fails too.

Each folder may include its own headers and those of the folders below it;
an include that climbs (transforms/ including plugin/, report/ including
jobs/) is named with its file and line and fails the test. spectral/ also
includes no OpenColorIO header (the exact core knows nothing of OCIO), and
only imageio/ImageFilesModule.cpp includes OpenImageIO (the module the
library loads when it touches an image).

Usage: check_layers.py SOURCE_DIR
"""
import pathlib
import re
import sys

# Each layer and the layers it may include (its own included).
BELOW = {
    "spectral": [],
    "transforms": ["spectral"],
    "render": ["spectral", "transforms"],
    "luts": ["spectral", "transforms"],
    "plugin": ["spectral", "transforms", "luts"],
    "imageio": ["spectral", "transforms", "luts", "plugin"],
    "farm": ["spectral"],
    "requests": ["spectral", "transforms", "render", "luts", "plugin", "imageio", "farm"],
    "imaging": ["spectral", "transforms", "render", "luts", "plugin", "imageio", "farm",
                "requests"],
    "camera": ["spectral", "transforms", "luts", "plugin", "imageio", "farm", "requests"],
    "report": ["spectral", "transforms", "render", "luts", "plugin", "imageio", "farm",
               "requests"],
    "measure": ["spectral", "transforms", "render", "luts", "plugin", "imageio", "farm",
                "requests", "imaging", "report"],
    "jobs": ["spectral", "transforms", "render", "luts", "plugin", "imageio", "farm", "requests",
             "imaging", "camera", "measure", "report"],
    "api": ["spectral", "transforms", "render", "luts", "plugin", "imageio", "farm", "requests",
            "imaging", "camera", "measure", "report", "jobs"],
}
# The faces: they may include every library layer, and never each other.
FACES = ["cli", "python/src", "bench"]

INCLUDE = re.compile(r'^\s*#\s*include\s*[<"]([^>"]+)[>"]')


def includes(path):
    for number, line in enumerate(path.read_text(errors="replace").splitlines(), 1):
        m = INCLUDE.match(line)
        if m:
            yield number, m.group(1)


def main():
    root = pathlib.Path(sys.argv[1])
    problems = []
    checked = 0
    folders = {**{k: BELOW[k] + [k] for k in BELOW}, **{f: list(BELOW) for f in FACES}}
    for folder, allowed in folders.items():
        for path in sorted((root / folder).rglob("*")):
            if path.suffix not in (".h", ".cpp"):
                continue
            checked += 1
            where = path.relative_to(root)
            for number, target in includes(path):
                m = re.match(r"([a-z]+)/", target)
                if m and m.group(1) in BELOW and not (root / target).is_file():
                    problems.append(f"{where}:{number}: includes {target}, which is no file "
                                    f"of the checkout")
                if m and m.group(1) in BELOW and m.group(1) not in allowed:
                    problems.append(f"{where}:{number}: includes {target}: "
                                    f"{folder}/ may include only {', '.join(allowed)}")
                if folder == "spectral" and target.startswith("OpenColorIO/"):
                    problems.append(f"{where}:{number}: spectral/ includes OpenColorIO")
                if target.startswith("OpenImageIO/") and path.name != "ImageFilesModule.cpp":
                    problems.append(f"{where}:{number}: includes OpenImageIO outside the image module")
    if checked < 100:
        problems.append(f"only {checked} sources found under {root}: wrong folder?")
    for p in problems:
        print(p)
    print(f"{checked} sources checked, {len(problems)} includes against the layers")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
