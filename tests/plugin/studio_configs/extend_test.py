#!/usr/bin/python3
"""`bandlight config --base` on studio configs of every kind, checked as a TD would.

    extend_test.py BANDLIGHT_EXE WORK_DIR

Writes the test configs (make_*.py, from the published definitions of the
formats they imitate) into WORK_DIR, then for each of them and for Blender's
own config when it is installed:

  1. `bandlight config --base` exits 0 and `ociocheck` passes on the result;
  2. every base colour space, display/view, look and named transform gives the
     same pixels in the result (pixels.py --compare: 1e-6 against the base as
     OCIO re-serialises it, 1e-5 against the original file);
  3. with bandlight's additions removed, the result serialises to the same
     text as the base re-serialised by OpenColorIO (nothing of the base lost);
  4. the bradford A -> D65 look (written for lit plates) equals an independent Bradford matrix in the
     primaries bandlight identified (2e-3), and those primaries are the ones
     the config was built with;
  5. the base folder and the result moved together still work (relative
     search paths).
Exit status 0 when every check passes. Needs PyOpenColorIO (python3-pyopencolorio).
"""
import os
import shutil
import subprocess
import sys

import PyOpenColorIO as OCIO

HERE = os.path.dirname(os.path.abspath(__file__))
BLENDER = "/usr/share/blender/datafiles/colormanagement/config.ocio"

# Each test config, and the primaries its scene_linear space has (by construction).
CONFIGS = [
    ("nuke-default", "rec709"),
    ("show-v1", "rec709"),
    ("aces-studio-v2.1", "acescg"),
    ("agx-xyzE-ref", "rec709"),
    ("minimal-srgb-v2", "rec709"),
]

# Chromaticities for the independent check (x, y of R, G, B, white).
PRIMARIES = {
    "rec709": ((0.64, 0.33), (0.30, 0.60), (0.15, 0.06), (0.3127, 0.3290)),
    "acescg": ((0.713, 0.293), (0.165, 0.830), (0.128, 0.044), (0.32168, 0.33767)),
}

failures = []


def check(ok, what):
    print(("ok    " if ok else "FAIL  ") + what)
    if not ok:
        failures.append(what)


# --- an independent Bradford matrix (no bandlight code) -----------------------

def inv3(m):
    a, b, c = m[0]
    d, e, f = m[1]
    g, h, i = m[2]
    det = a * (e * i - f * h) - b * (d * i - f * g) + c * (d * h - e * g)
    return [[(e * i - f * h) / det, (c * h - b * i) / det, (b * f - c * e) / det],
            [(f * g - d * i) / det, (a * i - c * g) / det, (c * d - a * f) / det],
            [(d * h - e * g) / det, (b * g - a * h) / det, (a * e - b * d) / det]]


def mul3(a, b):
    return [[sum(a[i][k] * b[k][j] for k in range(3)) for j in range(3)] for i in range(3)]


def vec3(a, v):
    return [sum(a[i][k] * v[k] for k in range(3)) for i in range(3)]


def rgb_to_xyz(prim):
    cols = [[x / y, 1.0, (1 - x - y) / y] for (x, y) in prim[:3]]
    m = [[cols[j][i] for j in range(3)] for i in range(3)]
    wx, wy = prim[3]
    s = vec3(inv3(m), [wx / wy, 1.0, (1 - wx - wy) / wy])
    return [[m[i][j] * s[j] for j in range(3)] for i in range(3)]


BRADFORD = [[0.8951, 0.2664, -0.1614], [-0.7502, 1.7135, 0.0367], [0.0389, -0.0685, 1.0296]]
# CIE 15:2004 Table T.3, 2 degree observer: white points of A and D65 (Y = 1).
WHITE_A = [1.09850, 1.0, 0.35585]
WHITE_D65 = [0.95047, 1.0, 1.08883]


def bradford_in(primaries):
    ls, ld = vec3(BRADFORD, WHITE_A), vec3(BRADFORD, WHITE_D65)
    d = [[ld[0] / ls[0], 0, 0], [0, ld[1] / ls[1], 0], [0, 0, ld[2] / ls[2]]]
    cat = mul3(inv3(BRADFORD), mul3(d, BRADFORD))
    m = rgb_to_xyz(PRIMARIES[primaries])
    return mul3(inv3(m), mul3(cat, m))


def measured_look(config_path, look):
    cfg = OCIO.Config.CreateFromFile(config_path)
    t = OCIO.LookTransform(src=OCIO.ROLE_SCENE_LINEAR, dst=OCIO.ROLE_SCENE_LINEAR, looks=look)
    cpu = cfg.getProcessor(t).getDefaultCPUProcessor()
    cols = [cpu.applyRGB([1.0 if i == c else 0.0 for i in range(3)]) for c in range(3)]
    return [[cols[c][r] for c in range(3)] for r in range(3)]


# --- nothing of the base lost --------------------------------------------------

def without_additions(ext_path, base_cfg):
    """The extended config with bandlight's looks, named transforms, band space
    and search paths taken back out."""
    ext = OCIO.Config.CreateFromFile(ext_path)
    base_looks = [l.getName() for l in base_cfg.getLooks()]
    looks = [ext.getLook(n) for n in base_looks]
    ext.clearLooks()
    for l in looks:
        ext.addLook(l)
    if ext.getMajorVersion() >= 2:
        base_nts = set(base_cfg.getNamedTransformNames())
        keep = [ext.getNamedTransform(n) for n in ext.getNamedTransformNames() if n in base_nts]
        ext.clearNamedTransforms()
        for nt in keep:
            ext.addNamedTransform(nt)
    ext.removeColorSpace("Bands VB-VG-VR (lecture)")
    ext.clearSearchPaths()
    for p in base_cfg.getSearchPaths():
        ext.addSearchPath(p)
    return ext


def main():
    exe, work = sys.argv[1], sys.argv[2]
    shutil.rmtree(work, ignore_errors=True)
    os.makedirs(work)
    for gen in ("make_nuke_show.py", "make_aces.py", "make_agx_minimal.py"):
        subprocess.run(["/usr/bin/python3", os.path.join(HERE, gen), work], check=True,
                       stdout=subprocess.DEVNULL)
    cases = [(os.path.join(work, name, "config.ocio"), name, prim) for name, prim in CONFIGS]
    if os.path.exists(BLENDER):
        cases.append((BLENDER, "blender", "rec709"))
    else:
        print("skip  Blender's config (package blender not installed)")

    for base_path, name, primaries in cases:
        out = os.path.join(work, "extended", name)
        r = subprocess.run([exe, "config", "--base", base_path, "--out", out, "--illuminants",
                            "A,D65,F11", "--methods", "bradford,band3,upsample",
                            "--lut-size", "17", "--plates", "lit"],
                           capture_output=True, text=True)
        check(r.returncode == 0, f"{name}: bandlight config --base exits 0 ({r.stderr.strip()})")
        if r.returncode != 0:
            continue
        print("      " + r.stdout.strip().replace("\n", "\n      "))
        check(f"for {primaries} " in r.stdout, f"{name}: scene_linear identified as {primaries}")
        oc = subprocess.run(["ociocheck", "--iconfig", os.path.join(out, "config.ocio")],
                            capture_output=True, text=True)
        check(oc.returncode == 0 and "ERROR" not in oc.stdout + oc.stderr,
              f"{name}: ociocheck passes on the result")
        # Against the base as OCIO re-serialises it (search paths made
        # absolute so it can live elsewhere): 1e-6. Against the original file:
        # 1e-5, because OCIO writes some numbers with fewer digits than a
        # config may give them (Blender's False Color and contrast looks move
        # by 1.3e-6 in a plain OCIO round trip).
        base_cfg = OCIO.Config.CreateFromFile(base_path)
        reser = OCIO.Config.CreateFromStream(base_cfg.serialize())
        reser.clearSearchPaths()
        for p in base_cfg.getSearchPaths():
            reser.addSearchPath(p if p.startswith(("/", "$")) else
                                os.path.join(os.path.dirname(base_path), p))
        reser_path = os.path.join(work, "reserialised", name, "config.ocio")
        os.makedirs(os.path.dirname(reser_path), exist_ok=True)
        with open(reser_path, "w") as f:
            f.write(reser.serialize())
        # (OCIO 2.1 drops a v1 config's `environment:` when it serialises
        # one, so a v1 base is compared with its original file at 1e-6.)
        references = ([(base_path, "1e-6")] if base_cfg.getMajorVersion() < 2 else
                      [(reser_path, "1e-6"), (base_path, "1e-5")])
        for reference, tol in references:
            cmp = subprocess.run(["/usr/bin/python3", os.path.join(HERE, "pixels.py"),
                                  "--compare", reference, os.path.join(out, "config.ocio"),
                                  "--tol", tol], capture_output=True, text=True)
            last = cmp.stdout.strip().splitlines()[-1] if cmp.stdout.strip() else cmp.stderr
            check(cmp.returncode == 0,
                  f"{name}: every base transform gives the same pixels as the "
                  f"{'re-serialised' if reference == reser_path else 'original'} base "
                  f"({tol}; {last})")
        stripped = without_additions(os.path.join(out, "config.ocio"), base_cfg)
        check(stripped.serialize() == base_cfg.serialize(),
              f"{name}: without bandlight's additions the result is the base, text for text")
        m = measured_look(os.path.join(out, "config.ocio"), "bradford_A_to_D65")
        e = bradford_in(primaries)
        err = max(abs(m[i][j] - e[i][j]) for i in range(3) for j in range(3))
        check(err < 2e-3, f"{name}: bradford_A_to_D65 = independent Bradford matrix "
                          f"(max difference {err:.1e})")
        if base_path != BLENDER:
            # Move the base and the result together: relative paths still resolve.
            moved = os.path.join(work, "moved")
            shutil.rmtree(moved, ignore_errors=True)
            os.makedirs(os.path.join(moved, "extended"))
            shutil.copytree(os.path.dirname(base_path), os.path.join(moved, name))
            shutil.copytree(out, os.path.join(moved, "extended", name))
            cmp = subprocess.run(["/usr/bin/python3", os.path.join(HERE, "pixels.py"),
                                  "--compare", base_path,
                                  os.path.join(moved, "extended", name, "config.ocio"),
                                  "--tol", "1e-6"], capture_output=True, text=True)
            check(cmp.returncode == 0, f"{name}: the result moved with its base still works")
            shutil.rmtree(moved)
    print(f"{len(failures)} failures")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
