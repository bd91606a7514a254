#!/usr/bin/python3
"""Evaluate a fixed set of test pixels through every processor an OCIO config defines, print JSON.

  pixels.py CONFIG.ocio [--env NAME=VALUE ...] [-o OUT.json]
      For every colour space (active AND inactive, scene- and display-referred):
          colour space -> scene_linear  and  scene_linear -> colour space
      For every display (active and inactive) and every view of it (display-defined and shared):
          scene_linear -> (display, view)      [view looks applied, as an application would]
      For every look:  scene_linear -> look -> scene_linear  (forward, and inverse)
      For every named transform (v2):  forward and inverse.
      Errors (e.g. missing LUT, unresolved context variable) are recorded per entry, never fatal.

  pixels.py --compare BASE(.ocio|.json) EXTENDED(.ocio|.json) [--tol 1e-5] [--env NAME=VALUE ...]
      Compares two results pixel-for-pixel. Every entry of BASE must exist in EXTENDED with the same
      values (within --tol, relative to max(1,|value|)); entries only in EXTENDED are listed as added.
      Exit status 0 = all base entries identical, 1 = differences / missing entries.

Context variables: --env sets them in the process environment before the config is loaded
(so they override defaults from the config's `environment:` section, e.g. --env SHOT=sh020).
Needs /usr/bin/python3 with PyOpenColorIO (Debian: python3-pyopencolorio). No numpy needed.
"""
import argparse, json, math, os, sys

import PyOpenColorIO as OCIO

# ~20 RGB test pixels: neutrals across the range (incl. HDR and negative), primaries, secondaries,
# mixed/saturated colours, a skin tone and an out-of-gamut value.
PIXELS = [
    [0.0, 0.0, 0.0],
    [0.001, 0.001, 0.001],
    [0.0182, 0.0182, 0.0182],
    [0.18, 0.18, 0.18],
    [0.5, 0.5, 0.5],
    [0.75, 0.75, 0.75],
    [1.0, 1.0, 1.0],
    [4.0, 4.0, 4.0],
    [16.0, 16.0, 16.0],
    [-0.05, -0.02, -0.01],
    [1.0, 0.0, 0.0],
    [0.0, 1.0, 0.0],
    [0.0, 0.0, 1.0],
    [0.0, 1.0, 1.0],
    [1.0, 0.0, 1.0],
    [1.0, 1.0, 0.0],
    [0.6, 0.35, 0.25],
    [0.12, 0.28, 0.6],
    [0.9, 0.05, 0.4],
    [2.5, 0.8, 0.05],
    [-0.1, 0.4, 1.2],
]

SCENE_LINEAR = OCIO.ROLE_SCENE_LINEAR  # "scene_linear"


def _clean(v):
    if math.isnan(v):
        return "nan"
    if math.isinf(v):
        return "inf" if v > 0 else "-inf"
    return float("%.7g" % v)


def apply(proc):
    cpu = proc.getDefaultCPUProcessor()
    flat = [c for p in PIXELS for c in p]
    out = cpu.applyRGB(flat)
    return [[_clean(out[i + k]) for k in range(3)] for i in range(0, len(out), 3)]


def run(fn):
    try:
        return {"pixels": apply(fn())}
    except Exception as e:  # OCIO.Exception and friends
        return {"error": str(e).strip()}


def evaluate(path):
    cfg = OCIO.Config.CreateFromFile(path)
    ctx = cfg.getCurrentContext()
    res = {
        "config": os.path.abspath(path),
        "ocio_version": OCIO.__version__,
        "profile_version": "%d.%d" % (cfg.getMajorVersion(), cfg.getMinorVersion()),
        "scene_linear": cfg.getColorSpace(SCENE_LINEAR).getName() if cfg.hasRole(SCENE_LINEAR) else None,
        "context": {k: ctx.resolveStringVar("$" + k) for k in cfg.getEnvironmentVarNames()},
        "test_pixels": PIXELS,
        "colorspaces": {},
        "displays": {},
        "looks": {},
        "named_transforms": {},
    }
    if res["scene_linear"] is None:
        res["error"] = "config has no scene_linear role"
        return res

    active_cs = set(cfg.getColorSpaceNames())
    for cs in cfg.getColorSpaces(OCIO.SEARCH_REFERENCE_SPACE_ALL, OCIO.COLORSPACE_ALL):
        n = cs.getName()
        e = {
            "active": n in active_cs,
            "reference_type": "display" if cs.getReferenceSpaceType() == OCIO.REFERENCE_SPACE_DISPLAY else "scene",
            "isdata": cs.isData(),
        }
        e["to_scene_linear"] = run(lambda: cfg.getProcessor(ctx, n, SCENE_LINEAR))
        e["from_scene_linear"] = run(lambda: cfg.getProcessor(ctx, SCENE_LINEAR, n))
        res["colorspaces"][n] = e

    active_disp = list(cfg.getDisplays())
    for disp in cfg.getDisplaysAll():
        active_views = list(cfg.getViews(disp)) if disp in active_disp else []
        views = list(cfg.getViews(OCIO.VIEW_DISPLAY_DEFINED, disp)) + \
            [v for v in cfg.getViews(OCIO.VIEW_SHARED, disp)]
        dres = {}
        for view in views:
            e = {
                "active": view in active_views,
                "display_active": disp in active_disp,
                "colorspace": cfg.getDisplayViewColorSpaceName(disp, view),
                "view_transform": cfg.getDisplayViewTransformName(disp, view),
                "looks": cfg.getDisplayViewLooks(disp, view),
            }

            def mk(d=disp, v=view):
                t = OCIO.DisplayViewTransform(src=SCENE_LINEAR, display=d, view=v)
                return cfg.getProcessor(ctx, t, OCIO.TRANSFORM_DIR_FORWARD)
            e["scene_linear_to_view"] = run(mk)
            dres[view] = e
        res["displays"][disp] = {"active": disp in active_disp, "views": dres}
    res["default_display"] = cfg.getDefaultDisplay()
    res["default_view"] = cfg.getDefaultView(cfg.getDefaultDisplay()) if cfg.getDefaultDisplay() else None

    for lk in cfg.getLooks():
        n = lk.getName()
        e = {"process_space": lk.getProcessSpace()}
        for key, direction in (("forward", OCIO.TRANSFORM_DIR_FORWARD), ("inverse", OCIO.TRANSFORM_DIR_INVERSE)):
            def mk(n=n, direction=direction):
                t = OCIO.LookTransform(src=SCENE_LINEAR, dst=SCENE_LINEAR, looks=n)
                return cfg.getProcessor(ctx, t, direction)
            e[key] = run(mk)
        res["looks"][n] = e

    for nt in cfg.getNamedTransforms(OCIO.NAMEDTRANSFORM_ALL):
        n = nt.getName()
        e = {}
        for key, direction, other in (("forward", OCIO.TRANSFORM_DIR_FORWARD, OCIO.TRANSFORM_DIR_INVERSE),
                                      ("inverse", OCIO.TRANSFORM_DIR_INVERSE, OCIO.TRANSFORM_DIR_FORWARD)):
            def mk(nt=nt, direction=direction, other=other):
                t = nt.getTransform(direction)
                if t is not None:
                    return cfg.getProcessor(ctx, t, OCIO.TRANSFORM_DIR_FORWARD)
                return cfg.getProcessor(ctx, nt.getTransform(other), OCIO.TRANSFORM_DIR_INVERSE)
            e[key] = run(mk)
        res["named_transforms"][n] = e
    return res


# ---------------------------------------------------------------------------- compare

def _leaves(d, prefix=()):
    """Yield (path, value) for every {"pixels": ...} / {"error": ...} leaf."""
    if isinstance(d, dict):
        if "pixels" in d or "error" in d:
            yield prefix, d
            return
        for k, v in d.items():
            if k in ("test_pixels", "context", "config"):
                continue
            yield from _leaves(v, prefix + (k,))


def _load(p):
    if p.endswith(".json"):
        with open(p) as f:
            return json.load(f)
    return evaluate(p)


def compare(a, b, tol):
    la = dict(_leaves({k: a[k] for k in ("colorspaces", "displays", "looks", "named_transforms")}))
    lb = dict(_leaves({k: b[k] for k in ("colorspaces", "displays", "looks", "named_transforms")}))
    bad = 0
    for path, va in la.items():
        name = " / ".join(path)
        vb = lb.get(path)
        if vb is None:
            print("MISSING in extended: %s" % name)
            bad += 1
            continue
        if "error" in va or "error" in vb:
            if va.get("error") != vb.get("error"):
                print("ERROR DIFFERS: %s\n   base: %s\n   ext:  %s" % (name, va.get("error", "ok"), vb.get("error", "ok")))
                bad += 1
            continue
        worst = 0.0
        where = None
        for i, (pa, pb) in enumerate(zip(va["pixels"], vb["pixels"])):
            for x, y in zip(pa, pb):
                if isinstance(x, str) or isinstance(y, str):
                    d = 0.0 if x == y else float("inf")
                else:
                    d = abs(x - y) / max(1.0, abs(x))
                if d > worst:
                    worst, where = d, (i, pa, pb)
        if worst > tol:
            i, pa, pb = where
            print("DIFF %.3g: %s  (pixel %s %s: base %s ext %s)" % (worst, name, i, PIXELS[i], pa, pb))
            bad += 1
    added = [" / ".join(p) for p in lb if p not in la]
    for n in added:
        print("added in extended: %s" % n)
    # visibility changes (an extension must not hide or un-hide what the base shows)
    for n, ea in a["colorspaces"].items():
        eb = b["colorspaces"].get(n)
        if eb is not None and ea["active"] != eb["active"]:
            print("ACTIVE FLAG differs: colorspace %s (base %s, extended %s)" % (n, ea["active"], eb["active"]))
            bad += 1
    for dn, da in a["displays"].items():
        db = b["displays"].get(dn)
        if db is None:
            continue
        if da["active"] != db["active"]:
            print("ACTIVE FLAG differs: display %s (base %s, extended %s)" % (dn, da["active"], db["active"]))
            bad += 1
        for vn, va in da["views"].items():
            vb = db["views"].get(vn)
            if vb is not None and va["active"] != vb["active"]:
                print("ACTIVE FLAG differs: view %s / %s (base %s, extended %s)" % (dn, vn, va["active"], vb["active"]))
                bad += 1
    for key in ("scene_linear", "default_display", "default_view"):
        if a.get(key) != b.get(key):
            print("%s differs: base %r, extended %r" % (key, a.get(key), b.get(key)))
            bad += 1
    print("%d base entries compared, %d problems, %d entries added" % (len(la), bad, len(added)))
    return 0 if bad == 0 else 1


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("config", nargs="?")
    ap.add_argument("--compare", nargs=2, metavar=("BASE", "EXTENDED"))
    ap.add_argument("--tol", type=float, default=1e-5)
    ap.add_argument("--env", action="append", default=[], metavar="NAME=VALUE")
    ap.add_argument("-o", "--output")
    args = ap.parse_args()
    for kv in args.env:
        k, _, v = kv.partition("=")
        os.environ[k] = v
    OCIO.SetLoggingLevel(OCIO.LOGGING_LEVEL_NONE)
    if args.compare:
        sys.exit(compare(_load(args.compare[0]), _load(args.compare[1]), args.tol))
    if not args.config:
        ap.error("give a config path or --compare BASE EXTENDED")
    text = json.dumps(evaluate(args.config), indent=1)
    if args.output:
        with open(args.output, "w") as f:
            f.write(text + "\n")
    else:
        print(text)


if __name__ == "__main__":
    main()
