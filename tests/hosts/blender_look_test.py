#!/usr/bin/python3
"""Blender applies a bandlight look as OpenColorIO does.

    blender_look_test.py BANDLIGHT_EXE WORK_DIR

Writes the default package (`bandlight package`: ACEScg working space, an sRGB
display with the views Standard and Raw, the roles Blender reads) into
WORK_DIR/pkg and a 16x8 float EXR test image (greys 2^-8 ... 16, the six
saturated ACEScg primaries and secondaries at the same levels), then runs
Blender headless with OCIO=WORK_DIR/pkg/config.ocio on this same file: in
Blender it builds a compositor tree, Image (colour space ACEScg) -> Composite,
and saves the render as a user does with "Save as Render". Checked:

  1. Blender offers every look of the config for every view (Render
     Properties -> Color Management -> Look lists looks by their config name;
     it hides a look only for other views when the name is "<view> - <look>",
     which bandlight's names never are);
  2. for band3_A_to_D65 and bradford_A_to_D65 under the views Standard and
     Raw: the 16-bit PNG Blender writes equals OCIO's CPU processor of the
     display/view with the look as an override (the way OCIO's own viewing
     pipeline applies looks), clipped to [0, 1], to half a code value plus
     1e-5; and the look visibly moves those pixels;
  3. a float EXR of the same render is the working-space image itself:
     Blender 3.4 applies the view and the look only to display-referred
     files, never to EXR (so a look can only be read back from an integer
     file, and pixels above 1 after the view are not compared);
  4. the compositor's Convert Colorspace node from ACEScg to "Linear Rec.709
     (sRGB)" and to the band space "Bands VB-VG-VR (lecture)", saved as float
     EXR, equals OCIO's processor for that conversion to 1e-5.

Images are written and read by oiiotool (openimageio-tools), not by Blender,
so Blender is checked against independent readers and writers; the reference
is PyOpenColorIO (python3-pyopencolorio). Blender runs single-threaded
(-t 1) and takes a few seconds. Prints "skipped: ..." and exits 0 when
Blender is not installed; otherwise exit status 0 when every check passes.
"""
import json
import os
import re
import shutil
import struct
import subprocess
import sys
import time

BLENDER = "/usr/bin/blender"
WORKING_SPACE = "ACEScg"
DISPLAY = "sRGB"
VIEWS = ["Standard", "Raw"]
LOOKS = ["band3_A_to_D65", "bradford_A_to_D65"]
CONVERSIONS = [("rec709", "Linear Rec.709 (sRGB)"), ("bands", "Bands VB-VG-VR (lecture)")]
WIDTH, HEIGHT = 16, 8

TOL_FLOAT = 1e-5
# A 16-bit PNG holds round(65535 v): the exact answer is within half a code value.
TOL_PNG = 0.5 / 65535 + TOL_FLOAT

failures = []


def check(ok, what):
    print(("ok    " if ok else "FAIL  ") + what)
    if not ok:
        failures.append(what)


# --- the test image and image files ------------------------------------------

def test_pixels():
    """WIDTH x HEIGHT RGB, row by row: two rows of greys from 2^-8 to 16 in
    equal steps of stops, then one row per saturated ACEScg colour (the
    primaries and secondaries, which leave the Rec.709 gamut) at 16 levels
    from 2^-8 to 16."""
    hues = [(1, 0, 0), (0, 1, 0), (0, 0, 1), (0, 1, 1), (1, 0, 1), (1, 1, 0)]
    assert HEIGHT == 2 + len(hues)
    px = []
    for i in range(2 * WIDTH):
        v = 2.0 ** (-8 + 12 * i / (2 * WIDTH - 1))
        px.append([v, v, v])
    for hue in hues:
        for i in range(WIDTH):
            v = 2.0 ** (-8 + 12 * i / (WIDTH - 1))
            px.append([c * v for c in hue])
    return px


def write_exr(path, px, work):
    """A float RGB EXR, through a Portable Float Map that oiiotool converts
    (PFM: a three-line header, then little-endian floats, bottom row first)."""
    pfm = os.path.join(work, "input.pfm")
    with open(pfm, "wb") as f:
        f.write(b"PF\n%d %d\n-1.0\n" % (WIDTH, HEIGHT))
        for y in reversed(range(HEIGHT)):
            row = [c for p in px[y * WIDTH:(y + 1) * WIDTH] for c in p]
            f.write(struct.pack("<%df" % len(row), *row))
    subprocess.run(["oiiotool", pfm, "-d", "float", "-o", path], check=True)


def read_image(path):
    """The RGB pixels of an image as floats, row by row, read by oiiotool.
    Integer files give their code values over the largest code (what a
    16-bit PNG holds, exactly); float files their values (printed with 9
    significant digits, which round-trips float32)."""
    out = subprocess.run(["oiiotool", "--dumpdata", path], capture_output=True,
                         text=True, check=True).stdout
    head = re.search(r":\s*(\d+) x\s*(\d+), (\d+) channel, (\w+)", out)
    w, h, nch, dtype = int(head[1]), int(head[2]), int(head[3]), head[4]
    scale = {"uint8": 255.0, "uint16": 65535.0}.get(dtype, 1.0)
    px = [None] * (w * h)
    for m in re.finditer(r"Pixel \((\d+), (\d+)\):([^\n(]*)", out):
        vals = [float(v) / scale for v in m[3].split()]
        px[int(m[2]) * w + int(m[1])] = vals[:3]
    assert (w, h) == (WIDTH, HEIGHT) and nch >= 3 and None not in px, path
    return px


def flat(px):
    return [c for p in px for c in p]


# --- the part that runs inside Blender ----------------------------------------

def in_blender(bpy, job):
    """Build the compositor tree, render, save every output the job names,
    and record which looks Blender accepts for each view."""
    scene = bpy.context.scene
    # Nothing 3D is rendered: the tree has no Render Layers node. The output
    # is the test image, pixel for pixel.
    scene.render.engine = 'BLENDER_WORKBENCH'
    scene.render.resolution_x, scene.render.resolution_y = WIDTH, HEIGHT
    scene.render.resolution_percentage = 100
    scene.render.dither_intensity = 0.0  # no noise added when quantising
    scene.display_settings.display_device = DISPLAY
    vs = scene.view_settings
    vs.exposure, vs.gamma, vs.use_curve_mapping = 0.0, 1.0, False

    # The Look menu: an enum that Blender fills per view from the config.
    rejected = {}
    for view in VIEWS:
        vs.view_transform = view
        rejected[view] = []
        for look in job["all_looks"]:
            try:
                vs.look = look
            except TypeError:
                rejected[view].append(look)

    scene.use_nodes = True
    tree = scene.node_tree
    for node in list(tree.nodes):
        tree.nodes.remove(node)
    image = bpy.data.images.load(job["input"])
    image.colorspace_settings.name = WORKING_SPACE
    src = tree.nodes.new("CompositorNodeImage")
    src.image = image
    out = tree.nodes.new("CompositorNodeComposite")
    fmt = scene.render.image_settings
    fmt.color_management = 'FOLLOW_SCENE'
    fmt.color_mode = 'RGB'

    def render(socket):
        tree.links.new(socket, out.inputs["Image"])
        bpy.ops.render.render()
        return bpy.data.images["Render Result"]

    def save(result, path, file_format):
        fmt.file_format = file_format
        if file_format == 'PNG':
            fmt.color_depth = '16'
        else:
            fmt.color_depth, fmt.exr_codec = '32', 'ZIP'
        # Image -> Save As with "Save as Render": the scene's display, view and look.
        result.save_render(filepath=path, scene=scene)

    result = render(src.outputs["Image"])
    for view, look, path in job["displayed"]:
        vs.view_transform = view
        vs.look = look
        save(result, path, 'PNG')
    vs.view_transform, vs.look = job["exr_with_look"][:2]
    save(result, job["exr_with_look"][2], 'OPEN_EXR')

    for dst, path in job["converted"]:
        conv = tree.nodes.new("CompositorNodeConvertColorSpace")
        conv.from_color_space, conv.to_color_space = WORKING_SPACE, dst
        tree.links.new(src.outputs["Image"], conv.inputs["Image"])
        save(render(conv.outputs["Image"]), path, 'OPEN_EXR')

    with open(job["report"], "w") as f:
        json.dump({"version": bpy.app.version_string, "rejected": rejected}, f)


# --- the driver ------------------------------------------------------------------

def max_diff(a, b):
    return max(abs(x - y) for x, y in zip(a, b))


def clip(values):
    return [min(max(v, 0.0), 1.0) for v in values]


def main():
    if not os.path.exists(BLENDER):
        print("skipped: blender is not installed")
        return 0
    import PyOpenColorIO as OCIO

    exe, work = sys.argv[1], os.path.abspath(sys.argv[2])
    shutil.rmtree(work, ignore_errors=True)
    os.makedirs(work)
    # Only the config file decides what Blender and the reference see.
    for var in ("OCIO_ACTIVE_DISPLAYS", "OCIO_ACTIVE_VIEWS", "OCIO_INACTIVE_COLORSPACES"):
        os.environ.pop(var, None)
    start = time.monotonic()

    pkg = os.path.join(work, "pkg")
    r = subprocess.run([exe, "package", "--out", pkg], capture_output=True, text=True)
    check(r.returncode == 0, "bandlight package exits 0"
          + ("" if r.returncode == 0 else f" ({r.stderr.strip()})"))
    if r.returncode != 0:
        return 1
    config_path = os.path.join(pkg, "config.ocio")
    config = OCIO.Config.CreateFromFile(config_path)
    all_looks = [look.getName() for look in config.getLooks()]

    input_path = os.path.join(work, "input.exr")
    write_exr(input_path, test_pixels(), work)
    src = flat(read_image(input_path))

    out = os.path.join(work, "blender")
    os.makedirs(out)
    job = {
        "input": input_path,
        "all_looks": all_looks,
        "displayed": [(view, look, os.path.join(out, f"{look}_{view}.png"))
                      for look in LOOKS for view in VIEWS],
        "exr_with_look": ("Standard", LOOKS[0], os.path.join(out, f"{LOOKS[0]}_Standard.exr")),
        "converted": [(dst, os.path.join(out, f"convert_{key}.exr")) for key, dst in CONVERSIONS],
        "report": os.path.join(out, "report.json"),
    }
    job_path = os.path.join(work, "job.json")
    with open(job_path, "w") as f:
        json.dump(job, f, indent=1)

    env = dict(os.environ, OCIO=config_path)
    r = subprocess.run([BLENDER, "-b", "--factory-startup", "-noaudio", "-t", "1",
                        "--python-exit-code", "1", "--python", os.path.abspath(__file__),
                        "--", job_path], env=env, capture_output=True, text=True, timeout=240)
    log = (r.stdout + r.stderr).strip().splitlines()
    check(r.returncode == 0, "Blender runs the compositor and saves every output"
          + ("" if r.returncode == 0 else " (exit %d):\n      %s"
             % (r.returncode, "\n      ".join(log[-15:]))))
    if r.returncode != 0:
        return 1
    with open(job["report"]) as f:
        report = json.load(f)

    # 1. The Look menu.
    for view in VIEWS:
        missing = report["rejected"][view]
        check(not missing, f"Blender {report['version']} offers all {len(all_looks)} looks "
                           f"for the view {view}" + (f" (not: {missing[:5]})" if missing else ""))

    # 2. Display-referred output with a look, against OCIO's viewing pipeline.
    def displayed(view, look):
        pipeline = OCIO.LegacyViewingPipeline()
        pipeline.setDisplayViewTransform(
            OCIO.DisplayViewTransform(src=WORKING_SPACE, display=DISPLAY, view=view))
        if look:
            pipeline.setLooksOverrideEnabled(True)
            pipeline.setLooksOverride(look)
        cpu = pipeline.getProcessor(config).getDefaultCPUProcessor()
        return clip(cpu.applyRGB(list(src)))

    for view, look, path in job["displayed"]:
        got = flat(read_image(path))
        want = displayed(view, look)
        diff = max_diff(got, want)
        moved = max_diff(want, displayed(view, None))
        inside = sum(0.0 < v < 1.0 for v in want)
        check(diff <= TOL_PNG and moved > 100 * TOL_PNG,
              f"look {look}, view {view}: Blender's 16-bit PNG = OCIO's display/view with "
              f"the look, max difference {diff:.2e} ({diff * 65535:.2f} code values; "
              f"{inside} of {len(want)} channels inside (0, 1); the look moves them by up to "
              f"{moved:.3f})")

    # 3. Float EXR output carries no view and no look.
    view, look, path = job["exr_with_look"]
    diff = max_diff(flat(read_image(path)), src)
    check(diff <= TOL_FLOAT, f"a float EXR saved with view {view} and look {look} is the "
                             f"{WORKING_SPACE} image unchanged (max difference {diff:.2e}): "
                             f"Blender applies looks to display-referred files only")

    # 4. The Convert Colorspace node.
    for dst, path in job["converted"]:
        cpu = config.getProcessor(WORKING_SPACE, dst).getDefaultCPUProcessor()
        diff = max_diff(flat(read_image(path)), cpu.applyRGB(list(src)))
        check(diff <= TOL_FLOAT, f"Convert Colorspace {WORKING_SPACE} -> {dst}: Blender's "
                                 f"float EXR = OCIO's processor, max difference {diff:.2e}")

    print(f"{len(failures)} failures ({time.monotonic() - start:.1f} s)")
    return 1 if failures else 0


if __name__ == "__main__":
    try:
        import bpy  # only Blender's Python has it: this file is running inside Blender
    except ImportError:
        sys.exit(main())
    with open(sys.argv[sys.argv.index("--") + 1]) as job_file:
        in_blender(bpy, json.load(job_file))
