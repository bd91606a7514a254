#!/usr/bin/env python3
"""Regenerates bandlight's tables taken from colour-science (BSD-3-Clause).

    python3 data/extract_colour_science.py COLOUR_REPO [REV]

COLOUR_REPO is a git directory or checkout of
https://github.com/colour-science/colour (REV defaults to HEAD). The numbers
are written as they appear there (same text, no rounding), each file with a
header naming the standard and the file they were taken from:

- ref/cie224_ces.csv: the 99 colour evaluation samples of CIE 224:2017 and
  ANSI/IES TM-30-18, 380-780 nm at 1 nm, from
  colour/quality/datasets/tcs_cfi2017_1_nm.csv.gz (the 5 nm file beside it is
  this table's every fifth row).
- cmf/cie1931_2deg_xyz_1nm.csv, cmf/cie1964_10deg_xyz_1nm.csv: the CIE 1931
  2-degree and 1964 10-degree observers at 1 nm, 360-830 nm, from
  colour/colorimetry/datasets/cmfs.py (their 5 nm rows equal the 5 nm tables
  beside them, taken from colord-data).

and the test fixtures of tests/spectral/data/ taken from colour-science's own
tests (colour/quality/tests/), whose expected values were made with the CIE's
and the IES's calculators (see each file's header):

- cie224_sample_5nm.csv, cie224_sample_1nm.csv: the test spectra of
  test_cfi2017.py;
- cie224_expected_rf.csv: the 99 expected Rf,i of test_cfi2017.py (sample,
  FL1, FL2) and test_tm3018.py (FL2);
- ssi_hmi_1nm.csv: the HMI spectrum of test_ssi.py.
"""
import gzip
import os
import re
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))


def show(repo, rev, path):
    return subprocess.run(["git", "-C", repo, "show", f"{rev}:{path}"], check=True,
                          capture_output=True).stdout


def write(out, header, names, rows):
    with open(os.path.join(HERE, out), "w") as f:
        for line in header:
            f.write(f"# {line}\n")
        f.write("wavelength_nm," + ",".join(names) + "\n")
        for row in rows:
            f.write(",".join(row) + "\n")


def main():
    repo = sys.argv[1]
    rev = sys.argv[2] if len(sys.argv) > 2 else "HEAD"
    commit = subprocess.run(["git", "-C", repo, "rev-parse", rev], check=True,
                            capture_output=True, text=True).stdout.strip()

    path = "colour/quality/datasets/tcs_cfi2017_1_nm.csv.gz"
    text = gzip.decompress(show(repo, rev, path)).decode()
    rows = [line.strip().split(",") for line in text.splitlines() if line.strip()]
    assert len(rows) == 401 and all(len(r) == 100 for r in rows)
    rows = [[str(int(float(r[0])))] + r[1:] for r in rows]
    write("ref/cie224_ces.csv",
          ["CIE 224:2017 / ANSI/IES TM-30-18 colour evaluation samples CES01-CES99, spectral "
           "reflectance factors, 380-780 nm at 1 nm",
           f"Source: colour-science (BSD-3-Clause), {path} at {commit}",
           "Regenerate: python3 data/extract_colour_science.py COLOUR_REPO (values as there)"],
          [f"CES{i:02d}" for i in range(1, 100)], rows)

    path = "colour/colorimetry/datasets/cmfs.py"
    src = show(repo, rev, path).decode()
    src = src[src.index("DATA_CMFS_STANDARD_OBSERVER"):]
    for name, out, table, number in (("CIE 1931 2 Degree", "cie1931_2deg", "CIE 1931 2-degree", "T.4"),
                             ("CIE 1964 10 Degree", "cie1964_10deg", "CIE 1964 10-degree", "T.5")):
        key = f'"{name} Standard Observer": {{'
        body = src[src.index(key) + len(key):]
        body = body[:body.index("}")]
        rows = [[m.group(1)] + [v.strip() for v in m.group(2).split(",")]
                for m in re.finditer(r"(\d+):\s*\(([^)]*)\)", body)]
        assert len(rows) == 471 and rows[0][0] == "360" and rows[-1][0] == "830"
        write(f"cmf/{out}_xyz_1nm.csv",
              [f"{table} colour-matching functions at 1 nm, CIE 15:2004 Table {number} "
               "(CVRL's 1 nm table)",
               f"Source: colour-science (BSD-3-Clause), {path} at {commit}",
               "Regenerate: python3 data/extract_colour_science.py COLOUR_REPO (values as there)"],
              ["x_bar", "y_bar", "z_bar"], rows)
    write_tests(repo, rev, commit)


def python_dict(src, name):
    body = src[src.index(name + ": dict = {") :]
    body = body[: body.index("}")]
    return [(m.group(1), m.group(2)) for m in re.finditer(r"(\d+):\s*([-\d.e]+),", body)]


def lists_after(src, marker):
    """Every bracketed list of numbers that follows `marker` in src, in order."""
    out = []
    for part in src.split(marker)[1:]:
        body = part[part.index("[") + 1 : part.index("]")]
        out.append([v.strip() for v in body.split(",") if v.strip()])
    return out


def write_tests(repo, rev, commit):
    tests = os.path.join(HERE, "..", "tests", "spectral", "data")
    cfi = show(repo, rev, "colour/quality/tests/test_cfi2017.py").decode()
    calc = ("expected values made with the CIE's spreadsheet for CIE 224:2017, "
            "http://files.cie.co.at/933_TC1-90.zip (as that file's notes say)")
    for grid in ("5NM", "1NM"):
        rows = [[w, v] for w, v in python_dict(cfi, "DATA_SD_SAMPLE_" + grid)]
        with open(os.path.join(tests, f"cie224_sample_{grid.lower()[:-2]}nm.csv"), "w") as f:
            f.write(f"# Test spectrum of colour-science's test_cfi2017.py (DATA_SD_SAMPLE_{grid}), "
                    f"{calc}\n")
            f.write(f"# Source: colour-science (BSD-3-Clause), "
                    f"colour/quality/tests/test_cfi2017.py at {commit}\n")
            f.write("# Regenerate: python3 data/extract_colour_science.py COLOUR_REPO\n")
            f.write("wavelength_nm,sample\n")
            for r in rows:
                f.write(",".join(r) + "\n")
    cie = lists_after(cfi, "specification.R_s,")
    assert len(cie) == 3 and all(len(c) == 99 for c in cie)
    tm = show(repo, rev, "colour/quality/tests/test_tm3018.py").decode()
    ies = lists_after(tm, "specification.R_s,")
    assert len(ies) == 1 and len(ies[0]) == 99
    with open(os.path.join(tests, "cie224_expected_rf.csv"), "w") as f:
        f.write("# Special colour fidelity indices Rf,i of the 99 CES. Columns sample, F1, F2: "
                "CIE 224:2017, from the CIE's spreadsheet\n")
        f.write("#   (http://files.cie.co.at/933_TC1-90.zip), printed to 0.1; column F2_tm30: "
                "ANSI/IES TM-30-18, from the IES calculator\n")
        f.write("#   (http://media.ies.org/docs/errata/TM-30-18_tools_etc.zip), printed as "
                "integers. sample is cie224_sample_*.csv; F1, F2 are CIE FL1, FL2.\n")
        f.write(f"# Source: colour-science (BSD-3-Clause), colour/quality/tests/test_cfi2017.py "
                f"and test_tm3018.py at {commit}\n")
        f.write("# Regenerate: python3 data/extract_colour_science.py COLOUR_REPO\n")
        f.write("ces,sample,F1,F2,F2_tm30\n")
        for i in range(99):
            f.write(f"{i + 1},{cie[0][i]},{cie[1][i]},{cie[2][i]},{ies[0][i]}\n")
    ssi = show(repo, rev, "colour/quality/tests/test_ssi.py").decode()
    with open(os.path.join(tests, "ssi_hmi_1nm.csv"), "w") as f:
        f.write("# HMI spectrum of colour-science's test_ssi.py (DATA_HMI), 300-830 nm at 1 nm\n")
        f.write(f"# Source: colour-science (BSD-3-Clause), colour/quality/tests/test_ssi.py "
                f"at {commit}\n")
        f.write("# Regenerate: python3 data/extract_colour_science.py COLOUR_REPO\n")
        f.write("wavelength_nm,HMI\n")
        for w, v in python_dict(ssi, "DATA_HMI"):
            f.write(f"{w},{v}\n")


if __name__ == "__main__":
    main()
