#!/usr/bin/python3
"""bandlight relights the view-layer light groups of a Blender Cycles render.

    blender_lightgroups_test.py BANDLIGHT_EXE WORK_DIR

Runs Blender headless (Cycles on the CPU, 8 samples, no denoising) on a
small scene made here: a grey floor and two coloured spheres lit by a point
light in the light group "key" and a sun in the group "fill", under the
default grey world, which is in no group (so the beauty holds a residual the
groups do not). Blender writes a multilayer OpenEXR (32-bit float) with the
passes Combined, Combined_key, Combined_fill, Depth and Diffuse Color, and a
stamp note in its header. Then:

  1. `bandlight apply --light-group key=A:D65 --light-group fill=F11:D50
     --colorspace rec709` (Blender's scene-linear space, which its EXRs do
     not tag) finds the groups by name ("ViewLayer.Combined_key.R", ...) and says it
     read Blender/Cycles naming;
     without --colorspace, the untagged file is read as linear Rec.709
     (Blender's default), the same pixels, with a note naming the assumption;
  2. the relit key layer equals `bandlight apply --from A --to D65` of the
     key layer alone (extracted by oiiotool as a plain R, G, B image), to
     1e-6 of the brightest value;
  3. the new beauty is the relit groups plus the residual of the input
     (beauty - key - fill, the world) to 1e-6 of the brightest value;
  4. every other channel (alpha, Depth, Diffuse Color) and the header's
     stamp note are what Blender wrote, bit for bit / as text;
  5. relighting each group to its own light gives Blender's beauty back to
     1e-6 of the brightest value.

Images are read by oiiotool (openimageio-tools). Prints "skipped: ..." and
exits 0 when Blender or oiiotool is not installed; otherwise exit status 0
when every check passes.
"""
import os
import re
import shutil
import subprocess
import sys
import time

BLENDER = "/usr/bin/blender"
WIDTH, HEIGHT = 48, 32
NOTE = "bandlight light-group test"

failures = []


def check(ok, what):
    print(("ok    " if ok else "FAIL  ") + what)
    if not ok:
        failures.append(what)


def read_channels(path):
    """Every channel of an EXR as {name: [values, pixel by pixel]}, read by
    oiiotool (values printed with 9 significant digits: float32 exactly)."""
    info = subprocess.run(["oiiotool", "--info", "-v", path], capture_output=True, text=True,
                          check=True).stdout
    names = re.search(r"channel list: ([^\n]*)", info)[1].split(", ")
    out = subprocess.run(["oiiotool", "--dumpdata", path], capture_output=True, text=True,
                         check=True).stdout
    channels = {n: [] for n in names}
    for m in re.finditer(r"Pixel \((\d+), (\d+)\):([^\n]*)", out):
        values = [float(v) for v in m[3].split()]
        assert len(values) == len(names), path
        for n, v in zip(names, values):
            channels[n].append(v)
    return channels, info


# --- the part that runs inside Blender ----------------------------------------

def in_blender(bpy, exr):
    bpy.ops.wm.read_factory_settings(use_empty=True)
    scene = bpy.context.scene
    scene.render.engine = 'CYCLES'
    scene.cycles.device = 'CPU'
    scene.cycles.samples = 8
    scene.cycles.use_denoising = False
    scene.cycles.max_bounces = 2
    scene.render.resolution_x, scene.render.resolution_y = WIDTH, HEIGHT
    scene.render.resolution_percentage = 100
    scene.render.film_transparent = False
    scene.render.use_stamp_note = True
    scene.render.stamp_note_text = NOTE
    scene.render.use_stamp = False
    world = bpy.data.worlds.new("World")
    world.use_nodes = True
    world.node_tree.nodes["Background"].inputs["Color"].default_value = (0.05, 0.05, 0.05, 1)
    scene.world = world

    def material(name, rgb):
        m = bpy.data.materials.new(name)
        m.use_nodes = True
        m.node_tree.nodes["Principled BSDF"].inputs["Base Color"].default_value = (*rgb, 1)
        return m

    bpy.ops.mesh.primitive_plane_add(size=20, location=(0, 0, 0))
    bpy.context.object.data.materials.append(material("floor", (0.5, 0.5, 0.5)))
    for x, rgb in ((-1.2, (0.8, 0.2, 0.1)), (1.2, (0.1, 0.4, 0.8))):
        bpy.ops.mesh.primitive_uv_sphere_add(radius=1, location=(x, 0, 1))
        bpy.context.object.data.materials.append(material("sphere", rgb))

    view_layer = scene.view_layers[0]
    for group in ("key", "fill"):
        view_layer.lightgroups.add(name=group)
    key = bpy.data.lights.new("key", type='POINT')
    key.energy = 800
    key_object = bpy.data.objects.new("key", key)
    key_object.location = (-3, -3, 5)
    key_object.lightgroup = "key"
    fill = bpy.data.lights.new("fill", type='SUN')
    fill.energy = 2
    fill_object = bpy.data.objects.new("fill", fill)
    fill_object.rotation_euler = (0.6, 0.5, 0.3)
    fill_object.lightgroup = "fill"
    for o in (key_object, fill_object):
        scene.collection.objects.link(o)
    camera = bpy.data.objects.new("camera", bpy.data.cameras.new("camera"))
    camera.location = (0, -8, 4)
    camera.rotation_euler = (1.15, 0, 0)
    scene.collection.objects.link(camera)
    scene.camera = camera

    view_layer.use_pass_z = True
    view_layer.use_pass_diffuse_color = True
    settings = scene.render.image_settings
    settings.file_format = 'OPEN_EXR_MULTILAYER'
    settings.color_depth = '32'
    settings.exr_codec = 'ZIP'
    scene.render.filepath = exr
    bpy.ops.render.render(write_still=True)


# --- the checks ----------------------------------------------------------------

def main():
    if len(sys.argv) != 3:
        print(__doc__)
        return 2
    bandlight, work = sys.argv[1], sys.argv[2]
    if not os.path.exists(BLENDER) or not shutil.which("oiiotool"):
        print("skipped: Blender or oiiotool is not installed")
        return 0
    start = time.monotonic()
    shutil.rmtree(work, ignore_errors=True)
    os.makedirs(work)
    shot = os.path.join(work, "shot.exr")
    r = subprocess.run([BLENDER, "-b", "--factory-startup", "-noaudio", "-t", "2",
                        "--python-exit-code", "1", "--python", os.path.abspath(__file__),
                        "--", shot], capture_output=True, text=True, timeout=240)
    log = (r.stdout + r.stderr).strip().splitlines()
    check(r.returncode == 0 and os.path.exists(shot),
          "Blender renders the light groups into a multilayer EXR"
          + ("" if r.returncode == 0 else " (exit %d):\n      %s"
             % (r.returncode, "\n      ".join(log[-15:]))))
    if failures:
        return 1
    src, src_info = read_channels(shot)
    layer = next(n[:-len(".Combined.R")] for n in src if n.endswith(".Combined.R"))
    combined, key, fill = (f"{layer}.{p}" for p in ("Combined", "Combined_key", "Combined_fill"))
    check(all(f"{p}.{c}" in src for p in (combined, key, fill) for c in "RGB"),
          f"Blender {layer!r} holds Combined, Combined_key and Combined_fill")
    peak = max(max(src[f"{combined}.{c}"]) for c in "RGB")
    check(peak > 0, f"the render is lit (brightest value {peak:.3g})")

    out = os.path.join(work, "relit.exr")
    r = subprocess.run([bandlight, "apply", shot, out, "--light-group", "key=A:D65",
                        "--light-group", "fill=F11:D50", "--method", "bradford",
                        "--colorspace", "rec709"],
                       capture_output=True, text=True)
    check(r.returncode == 0, "bandlight apply --light-group relights the render"
          + ("" if r.returncode == 0 else ": " + r.stderr.strip()))
    if r.returncode != 0:
        return 1
    check("2 light groups" in r.stderr and "Blender/Cycles naming" in r.stderr
          and f"beauty {combined}" in r.stderr,
          "1. groups found by name, Blender/Cycles naming reported: " + r.stderr.strip())
    dst, dst_info = read_channels(out)

    # 1b. Without --colorspace: Blender's naming says Blender wrote the
    # untagged file, so it is read as Blender's linear Rec.709, the same
    # pixels as with --colorspace rec709, and the note says so.
    untagged = os.path.join(work, "relit_untagged.exr")
    r = subprocess.run([bandlight, "apply", shot, untagged, "--light-group", "key=A:D65",
                        "--light-group", "fill=F11:D50", "--method", "bradford"],
                       capture_output=True, text=True)
    same, _ = read_channels(untagged) if r.returncode == 0 else ({}, None)
    check(r.returncode == 0 and "Blender's default linear Rec.709" in r.stderr
          and all(same.get(n) == v for n, v in dst.items()),
          "1b. an untagged Blender render is read as linear Rec.709, as --colorspace rec709 "
          "reads it: " + r.stderr.strip())

    # 2. The key layer alone, relit as a plain image.
    alone = os.path.join(work, "key.exr")
    subprocess.run(["oiiotool", shot, "--ch", ",".join(f"{c}={key}.{c}" for c in "RGB"),
                    "-o", alone], check=True)
    alone_relit = os.path.join(work, "key_relit.exr")
    subprocess.run([bandlight, "apply", alone, alone_relit, "--from", "A", "--to", "D65",
                    "--method", "bradford", "--plates", "lit", "--colorspace", "rec709"],
                   check=True, capture_output=True)
    ref, _ = read_channels(alone_relit)
    diff = max(abs(a - b) for c in "RGB" for a, b in zip(dst[f"{key}.{c}"], ref[c]))
    moved = max(abs(a - b) for c in "RGB" for a, b in zip(dst[f"{key}.{c}"], src[f"{key}.{c}"]))
    check(diff <= 1e-6 * peak and moved > 1e-3 * peak,
          f"2. key relit as the same change relights a plain image (max difference {diff:.2e}, "
          f"moved by up to {moved:.3g})")

    # 3. Beauty = relit groups + the residual (the world, in no group).
    worst, residual_peak = 0.0, 0.0
    for c in "RGB":
        for i in range(len(src[f"{combined}.{c}"])):
            residual = src[f"{combined}.{c}"][i] - src[f"{key}.{c}"][i] - src[f"{fill}.{c}"][i]
            residual_peak = max(residual_peak, residual)
            worst = max(worst, abs(dst[f"{combined}.{c}"][i] - dst[f"{key}.{c}"][i]
                                   - dst[f"{fill}.{c}"][i] - residual))
    check(worst <= 1e-6 * peak and residual_peak > 1e-3,
          f"3. beauty = relit groups + residual to {worst / peak:.1e} of the brightest value "
          f"(the world's residual up to {residual_peak:.3g})")

    # 4. Everything else as Blender wrote it.
    others = [n for n in src if not any(n.startswith(p + ".") for p in (key, fill))
              and n not in (f"{combined}.{c}" for c in "RGB")]
    check(list(dst) == list(src), f"4. the same {len(src)} channels, in order")
    same = [n for n in others if dst.get(n) == src[n]]
    check(same == others, f"4. {len(others)} other channels unchanged: {', '.join(others)}")
    check(NOTE in src_info and NOTE in dst_info, "4. the stamp note in the header is kept")

    # 5. Each group to its own light: Blender's beauty back.
    same_path = os.path.join(work, "same.exr")
    subprocess.run([bandlight, "apply", shot, same_path, "--light-group", "key=A:A",
                    "--light-group", "fill=F11:F11"], check=True, capture_output=True)
    back, _ = read_channels(same_path)
    diff = max(abs(a - b) for c in "RGB"
               for a, b in zip(back[f"{combined}.{c}"], src[f"{combined}.{c}"]))
    check(diff <= 1e-6 * peak, f"5. identity relight gives the beauty back (max {diff:.2e})")

    print(f"{len(failures)} failures ({time.monotonic() - start:.1f} s)")
    return 1 if failures else 0


if __name__ == "__main__":
    try:
        import bpy  # only Blender's Python has it: this file is running inside Blender
    except ImportError:
        sys.exit(main())
    in_blender(bpy, sys.argv[sys.argv.index("--") + 1])
