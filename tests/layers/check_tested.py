#!/usr/bin/python3
# SPDX-License-Identifier: BSD-3-Clause
"""Every source file of the library, the public API and the command has a
test: a test file of its own name (Spectrum.cpp: SpectrumTest.cpp) or a test
that names it by its path from the repository's root ("Covers:
spectral/SpectrumCgats.cpp" in the test's opening comment, where a source is
exercised through another's entry points). Names the sources with neither
and fails.

    check_tested.py REPOSITORY_ROOT
"""
import pathlib
import sys

FLOORS = ["spectral", "transforms", "render", "luts", "plugin", "imageio", "farm", "requests",
          "imaging", "camera", "measure", "report", "jobs", "api", "cli"]


def main():
    root = pathlib.Path(sys.argv[1])
    tests = [p for p in (root / "tests").rglob("*")
             if p.is_file() and p.suffix in (".cpp", ".h", ".py", ".cmake", ".txt")]
    own = {p.stem for p in tests}
    text = "\n".join(p.read_text(errors="replace") for p in tests)
    sources = sorted(p for floor in FLOORS for p in (root / floor).rglob("*.cpp"))
    untested = [p.relative_to(root).as_posix() for p in sources
                if p.stem + "Test" not in own and p.relative_to(root).as_posix() not in text]
    if len(sources) < 100:
        untested.append(f"only {len(sources)} sources found under {root}: wrong folder?")
    for u in untested:
        print(f"{u}: no test of its name and no test naming it")
    print(f"{len(sources)} sources checked, {len(untested)} without a test")
    return 1 if untested else 0


if __name__ == "__main__":
    sys.exit(main())
