#!/usr/bin/env python3
"""Regenerates bandlight's embedded CIE tables from Debian's colord-data package.

    python3 data/extract_colord.py [/usr/share/colord]

Each colord CGATS file is rewritten as a CSV on a 5 nm grid (1 nm tables are
subsampled at the 5 nm points, which they contain exactly: no interpolation),
with a header naming the standard the numbers come from and the package file.
"""
import os
import sys

ROOT = sys.argv[1] if len(sys.argv) > 1 else "/usr/share/colord"
HERE = os.path.dirname(os.path.abspath(__file__))


def read_cgats(path):
    kw, fields, rows, mode = {}, [], [], None
    for line in open(path, encoding="latin-1"):
        t = line.split()
        if not t:
            continue
        if t[0] == "BEGIN_DATA_FORMAT":
            mode = "fmt"
        elif t[0] == "END_DATA_FORMAT":
            mode = None
        elif t[0] == "BEGIN_DATA":
            mode = "data"
        elif t[0] == "END_DATA":
            mode = None
        elif mode == "fmt":
            fields += t
        elif mode == "data":
            rows.append(t)
        elif len(t) >= 2:
            kw[t[0]] = t[1].strip('"')
    return kw, fields, rows


def spectral_columns(fields, kw):
    start = float(kw["SPECTRAL_START_NM"])
    end = float(kw["SPECTRAL_END_NM"])
    bands = int(kw["SPECTRAL_BANDS"])
    step = (end - start) / (bands - 1)
    cols = [i for i, f in enumerate(fields) if f.startswith("SPEC_")]
    assert len(cols) == bands, path
    return [(start + k * step, cols[k]) for k in range(bands)]


def write_csv(out, source, standard, names, wl_cols, rows):
    with open(os.path.join(HERE, out), "w") as f:
        f.write(f"# {standard}\n")
        f.write(f"# Source: Debian package colord-data, {source}\n")
        f.write("# Regenerate: python3 data/extract_colord.py (5 nm grid, values as in the package)\n")
        f.write("wavelength_nm," + ",".join(names) + "\n")
        for wl, col in wl_cols:
            if abs(wl - round(wl / 5) * 5) > 1e-6:
                continue
            f.write(f"{wl:g}," + ",".join(r[col] for r in rows) + "\n")


def main():
    cmfs = [("cmf/cie1931_2deg_xyz.csv", "cmf/CIE1931-2deg-XYZ.cmf",
             "CIE 1931 2-degree colour-matching functions, CIE 15:2004 Table T.4"),
            ("cmf/cie1964_10deg_xyz.csv", "cmf/CIE1964-10deg-XYZ.cmf",
             "CIE 1964 10-degree colour-matching functions, CIE 15:2004 Table T.5")]
    for out, src, std in cmfs:
        kw, fields, rows = read_cgats(os.path.join(ROOT, src))
        write_csv(out, "/usr/share/colord/" + src, std, ["x_bar", "y_bar", "z_bar"],
                  spectral_columns(fields, kw), rows)

    for name in ["A", "C", "D50", "D55", "D65", "E"] + [f"F{i}" for i in range(1, 13)]:
        src = f"illuminant/CIE-{name}.sp"
        kw, fields, rows = read_cgats(os.path.join(ROOT, src))
        std = {"A": "CIE standard illuminant A, CIE 15:2004 Table T.1",
               "D65": "CIE standard illuminant D65, CIE 15:2004 Table T.1",
               "E": "CIE equal-energy illuminant E"}.get(
            name, f"CIE illuminant {name}, CIE 15:2004 Tables T.1/T.6")
        write_csv(f"illuminant/{name}.csv", "/usr/share/colord/" + src, std, [name],
                  spectral_columns(fields, kw), rows)

    src = "ref/CIE-1986-daylight-SPD.cmf"
    kw, fields, rows = read_cgats(os.path.join(ROOT, src))
    write_csv("ref/daylight_basis.csv", "/usr/share/colord/" + src,
              "CIE daylight basis functions S0, S1, S2, CIE 15:2004 Table T.2",
              ["S0", "S1", "S2"], spectral_columns(fields, kw), rows)

    src = "ref/CIE-TCS.sp"
    kw, fields, rows = read_cgats(os.path.join(ROOT, src))
    ids = [r[fields.index("SAMPLE_ID")] for r in rows]
    write_csv("ref/tcs.csv", "/usr/share/colord/" + src,
              "CIE 13.3-1995 test colour samples TCS01-TCS14 (and TCS15, CIE 13.3 / JIS Z 8726), spectral radiance factors",
              ids, spectral_columns(fields, kw), rows)


if __name__ == "__main__":
    main()
