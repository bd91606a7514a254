#!/usr/bin/env python3
"""Regenerates bandlight's EBU Tech 3355 (TLCI-2012 / TLMF-2013) tables from
colour-science's copy of them.

    python3 data/extract_tlci.py PATH/TO/colour/quality/datasets/tlci2012.py [OUT_DIR]

The module is read as text and its literal tables taken with ast (it is never
imported): the camera sensitivities (Appendix 5), the daylight vectors
(Appendix 3), the Planckian and daylight loci (Appendix 2) and the 24 chart
reflectances (Appendix 4). Each becomes a CSV in OUT_DIR (default: data/ref
beside this script), numbers written without trailing zeros, with a header
naming Tech 3355's appendix and the array it was taken from.
"""
import ast
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
SOURCE = ("#   colour-science, colour/quality/datasets/tlci2012.py ({name}),\n"
          "#   BSD-3-Clause, Copyright 2013 Colour Developers\n")


def literals(path):
    """Every module-level NAME = literal (or NAME = np.array(literal))."""
    tree = ast.parse(open(path, encoding="utf-8").read())
    out = {}
    for node in tree.body:
        if isinstance(node, ast.AnnAssign):
            targets, value = [node.target], node.value
        elif isinstance(node, ast.Assign):
            targets, value = node.targets, node.value
        else:
            continue
        if isinstance(value, ast.Call) and value.args:
            value = value.args[0]
        try:
            v = ast.literal_eval(value)
        except (ValueError, TypeError, SyntaxError):
            continue
        for t in targets:
            if isinstance(t, ast.Name):
                out[t.id] = v
    return out


def num(v):
    return ("%.8f" % float(v)).rstrip("0").rstrip(".")


def grid(i):
    return str(380 + 5 * i)


def write(out_dir, name, header, rows):
    with open(os.path.join(out_dir, name), "w", encoding="utf-8") as f:
        f.write("".join(header))
        for r in rows:
            f.write(",".join(r) + "\n")


def main():
    if len(sys.argv) < 2:
        sys.exit(__doc__)
    t = literals(sys.argv[1])
    out_dir = sys.argv[2] if len(sys.argv) > 2 else os.path.join(HERE, "ref")
    regen = "# Regenerate: python3 data/extract_tlci.py PATH/TO/colour/quality/datasets/tlci2012.py\n"

    camera = t["DATA_CAMERA_SENSITIVITIES_TLCI2012"]
    assert len(camera) == 77
    write(out_dir, "tlci_camera.csv", [
        "# EBU standard camera spectral sensitivities r, g, b (each column sums to 1), "
        "380-760 nm at 5 nm\n",
        "# Source: EBU Tech 3355 (TLCI-2012 / TLMF-2013, March 2017), Appendix 5 "
        "(derived from EBU Tech 3353),\n",
        "#   as redistributed by\n", SOURCE.format(name="DATA_CAMERA_SENSITIVITIES_TLCI2012"),
        regen, "wavelength_nm,r,g,b\n"],
        [[grid(i)] + [num(v) for v in row] for i, row in enumerate(camera)])

    basis = t["DATA_DAYLIGHT_BASIS_TLCI2012"]
    assert len(basis) == 77
    write(out_dir, "tlci_daylight_basis.csv", [
        "# EBU Tech 3355 daylight radiation vectors S0, S1, S2, 380-760 nm at 5 nm. Tech 3355 "
        "attributes\n",
        "#   them to CIE 15:2004, but its odd 5 nm rows differ from CIE 15's Table T.2 "
        "(ref/daylight_basis.csv):\n",
        "#   TLCI's daylight reference is built from this table, as the standard prints it\n",
        "# Source: EBU Tech 3355 (March 2017), Appendix 3, as redistributed by\n",
        SOURCE.format(name="DATA_DAYLIGHT_BASIS_TLCI2012"), regen, "wavelength_nm,S0,S1,S2\n"],
        [[grid(i)] + [num(v) for v in row] for i, row in enumerate(basis)])

    for file, name, what in (
            ("tlci_planckian_locus.csv", "DATA_PLANCKIAN_LOCUS_TLCI2012", "Planckian radiator"),
            ("tlci_daylight_locus.csv", "DATA_DAYLIGHT_LOCUS_TLCI2012", "daylight (CIE D-series)")):
        write(out_dir, file, [
            "# EBU Tech 3355 " + what + " locus: CCT (K) and CIE 1931 chromaticity x, y, the "
            "table\n",
            "#   TLCI-2012 finds a light's correlated colour temperature against (Tech 3355 "
            "section 1.1.1)\n",
            "# Source: EBU Tech 3355 (March 2017), Appendix 2, as redistributed by\n",
            SOURCE.format(name=name), regen, "cct_K,x,y\n"],
            [[num(v) for v in row] for row in t[name]])

    names = t["NAMES_TCS_TLCI2012"]
    chart = t["DATA_TCS_TLCI2012"]
    assert len(names) == 24
    columns = [n.split(" (")[0].replace(" ", "_") for n in names]
    write(out_dir, "tlci_chart.csv", [
        "# EBU Tech 3355 test chart: spectral reflectances of the 24 ColorChecker patches, "
        "380-760 nm at 5 nm,\n",
        "#   in chart order. TLCI-2012 uses the 18 coloured patches (columns 1-18), TLMF-2013 "
        "all 24.\n",
        "#   Patches 1-18 follow BBC R&D Report 1988/2 (Tech 3355 prints a few values that "
        "differ from it);\n",
        "#   the greys 19-24 (white 9.5 .05 D, neutral 8 .23 D, 6.5 .44 D, 5 .70 D, "
        "3.5 1.05 D,\n",
        "#   black 2 1.5 D) are unpublished BBC R&D data\n",
        "# Source: EBU Tech 3355 (March 2017), Appendix 4, as redistributed by\n",
        SOURCE.format(name="DATA_TCS_TLCI2012 in NAMES_TCS_TLCI2012 order"), regen,
        "wavelength_nm," + ",".join(columns) + "\n"],
        [[grid(i)] + [num(chart[n][380 + 5 * i]) for n in names] for i in range(77)])


if __name__ == "__main__":
    main()
