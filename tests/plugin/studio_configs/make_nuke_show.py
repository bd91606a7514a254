#!/usr/bin/python3
"""Writes nuke-default/ (v1, nuke-default style) and show-v1/ (v1 show config built on it)."""
import os, shutil, sys
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from colormath import *

# The folder to write into: the first argument (default: beside this folder).
ROOT = sys.argv[1] if len(sys.argv) > 1 else os.path.dirname(os.path.dirname(os.path.abspath(__file__)))

# (colour space name, lut file, function, description)
LOG_LUTS = [
    ("rec709", "rec709.spi1d", rec709_to_lin, "Rec. 709 (Full Range) Display Space"),
    ("Cineon", "cineon.spi1d", cineon_to_lin, "Cineon (Log Film Scan)"),
    ("Panalog", "panalog.spi1d", panalog_to_lin, "Sony/Panavision Genesis Log Space"),
    ("REDLog", "redlog.spi1d", redlog_to_lin, "RED Log Space"),
    ("ViperLog", "viperlog.spi1d", viperlog_to_lin, "Viper Log Space"),
    ("AlexaV3LogC", "alexalogc.spi1d", logc3_to_lin, "Alexa Log C"),
    ("PLogLin", "ploglin.spi1d", ploglin_to_lin, "Josh Pines style pivoted log/lin conversion. 445->0.18"),
    ("SLog", "slog.spi1d", slog_to_lin, "Sony SLog"),
    ("SLog1", "slog1.spi1d", slog1_to_lin, "Sony SLog1"),
    ("SLog2", "slog2.spi1d", slog2_to_lin, "Sony SLog2"),
    ("SLog3", "slog3.spi1d", slog3_to_lin, "Sony SLog3"),
    ("CLog", "clog.spi1d", clog_to_lin, "Canon CLog"),
    ("Protune", "protune.spi1d", protune_to_lin, "GoPro Protune"),
]


def cs(name, desc, to_ref=None, from_ref=None, isdata=False, alloc="uniform", allocvars="[-0.125, 1.125]",
       family="", bitdepth="32f"):
    s = ["  - !<ColorSpace>",
         "    name: %s" % name,
         '    family: "%s"' % family,
         '    equalitygroup: ""',
         "    bitdepth: %s" % bitdepth,
         "    description: |",
         "      %s" % desc,
         "    isdata: %s" % ("true" if isdata else "false"),
         "    allocation: %s" % alloc]
    if allocvars:
        s.append("    allocationvars: %s" % allocvars)
    if to_ref:
        s.append("    to_reference: %s" % to_ref)
    if from_ref:
        s.append("    from_reference: %s" % from_ref)
    return "\n".join(s) + "\n"


def nuke_colorspaces():
    out = [cs("linear", "Scene-linear, high dynamic range. Used for rendering and compositing.",
              alloc="lg2", allocvars="[-15, 6]")]
    out.append(cs("sRGB", "Standard RGB Display Space",
                  to_ref="!<FileTransform> {src: srgb.spi1d, interpolation: linear}"))
    out.append(cs("sRGBf", "Standard RGB Display Space, but with additional range to preserve float highlights.",
                  to_ref="!<FileTransform> {src: srgbf.spi1d, interpolation: linear}", allocvars="[-0.125, 4.875]"))
    for name, lut, _fn, desc in LOG_LUTS:
        av = "[0, 1]" if name != "rec709" else "[-0.125, 1.125]"
        out.append(cs(name, desc, to_ref="!<FileTransform> {src: %s, interpolation: linear}" % lut, allocvars=av))
    for g in ("1.8", "2.2", "2.4"):
        out.append(cs("Gamma" + g, "Emulates a idealized Gamma %s display device." % g,
                      to_ref="!<ExponentTransform> {value: [%s, %s, %s, 1]}" % (g, g, g), allocvars="[0, 1]"))
    out.append(cs("raw", "Raw Data. Used for normals, points, etc.", isdata=True, allocvars=None))
    return out


NUKE_HEADER = """ocio_profile_version: 1

# nuke-default style config (structure of the OpenColorIO-Configs nuke-default profile).
# LUTs in luts/ were regenerated from the published formulas by tools/make_nuke_show.py.
search_path: luts
strictparsing: true
luma: [0.2126, 0.7152, 0.0722]

roles:
  color_picking: sRGB
  color_timing: Cineon
  compositing_log: Cineon
  data: raw
  default: raw
  matte_paint: sRGB
  reference: linear
  scene_linear: linear
  texture_paint: sRGB

displays:
  default:
    - !<View> {name: None, colorspace: raw}
    - !<View> {name: sRGB, colorspace: sRGB}
    - !<View> {name: rec709, colorspace: rec709}
    - !<View> {name: rec1886, colorspace: Gamma2.4}

active_displays: [default]
active_views: [sRGB, rec709, rec1886, None]

colorspaces:
"""


def write_nuke_luts(lutdir):
    os.makedirs(lutdir, exist_ok=True)
    write_spi1d(os.path.join(lutdir, "srgb.spi1d"), srgb_to_lin)
    write_spi1d(os.path.join(lutdir, "srgbf.spi1d"), srgb_to_lin, -0.125, 4.875, 4096)
    for _name, lut, fn, _d in LOG_LUTS:
        write_spi1d(os.path.join(lutdir, lut), fn)


def make_nuke_default():
    d = os.path.join(ROOT, "nuke-default")
    write_nuke_luts(os.path.join(d, "luts"))
    with open(os.path.join(d, "config.ocio"), "w") as f:
        f.write(NUKE_HEADER)
        f.write("\n".join(nuke_colorspaces()))


# ----------------------------------------------------------------------------
# show-v1: a show config layered on nuke-default
# ----------------------------------------------------------------------------

CC = """<?xml version="1.0" encoding="UTF-8"?>
<ColorCorrection id="%s">
  <SOPNode>
    <Description>%s</Description>
    <Slope>%s</Slope>
    <Offset>%s</Offset>
    <Power>%s</Power>
  </SOPNode>
  <SatNode>
    <Saturation>%s</Saturation>
  </SatNode>
</ColorCorrection>
"""

GRADES = {
    ("sq01", "sh010"): ("1.05 1.0 0.93", "0.01 0.0 -0.01", "1.0 1.0 1.02", "0.9"),
    ("sq01", "sh020"): ("0.92 1.0 1.08", "-0.005 0.0 0.012", "1.04 1.0 0.98", "1.15"),
    ("sq02", "sh030"): ("1.2 1.1 1.0", "0.0 0.0 0.0", "0.95 0.95 0.95", "0.7"),
}


def show_lut(r, g, b):
    # mild warm + contrast S-curve in Cineon code values (look LUT, 3D because of the cross-talk)
    def s(x):
        return min(max(0.5 + (x - 0.5) * 1.12 - 0.08 * (x - 0.5) ** 3, 0.0), 1.0)
    y = 0.3 * r + 0.59 * g + 0.11 * b
    r2, g2, b2 = [y + 0.9 * (c - y) for c in (r, g, b)]
    return (s(r2 + 0.008), s(g2), s(b2 - 0.01))


def make_show_v1():
    d = os.path.join(ROOT, "show-v1")
    write_nuke_luts(os.path.join(d, "luts"))
    os.makedirs(os.path.join(d, "looks"), exist_ok=True)
    write_cube3d(os.path.join(d, "looks", "show_look.cube"), show_lut, 17, "show look (Cineon in/out)")
    ccc = ['<?xml version="1.0" encoding="UTF-8"?>', '<ColorCorrectionCollection xmlns="urn:ASC:CDL:v1.01">']
    for (seq, shot), (sl, of, pw, sat) in GRADES.items():
        sd = os.path.join(d, "shots", seq, shot)
        os.makedirs(sd, exist_ok=True)
        body = CC % (shot, "%s/%s grade" % (seq, shot), sl, of, pw, sat)
        with open(os.path.join(sd, "shot_grade.cc"), "w") as f:
            f.write(body)
        ccc.append("\n".join(body.splitlines()[1:]))
    ccc.append("</ColorCorrectionCollection>\n")
    with open(os.path.join(d, "looks", "grades.ccc"), "w") as f:
        f.write("\n".join(ccc))

    # S-Gamut3.Cine -> Rec.709 (both D65, no CAT)
    sg_to_709 = mmul(minv(rgb_to_xyz(REC709, D65)), rgb_to_xyz(SGAMUT3_CINE, D65))

    extra = []
    extra.append(cs("SLog3-SGamut3Cine", "Sony S-Log3 S-Gamut3.Cine -> linear Rec.709 primaries",
                    family="Input/Sony", allocvars="[0, 1]",
                    to_ref="!<GroupTransform> {children: [!<FileTransform> {src: slog3.spi1d, interpolation: linear}, "
                           "!<MatrixTransform> {matrix: %s}]}" % fmt_m44(sg_to_709)))
    extra.append(cs("show_log", "Show grading log: ColorSpaceTransform to AlexaV3LogC (alias-like space)",
                    family="Show", allocvars="[0, 1]",
                    from_ref="!<ColorSpaceTransform> {src: linear, dst: AlexaV3LogC}"))
    extra.append(cs("show_sRGB_graded", "sRGB output with the show look baked in (LookTransform inside a colour space)",
                    family="Show", allocvars="[0, 1]",
                    from_ref="!<LookTransform> {src: linear, dst: sRGB, looks: show_cdl}"))
    extra.append(cs("editorial_rec709", "Editorial Rec.709: Cineon-graded rec709 via ColorSpaceTransform + CDL",
                    family="Show", allocvars="[0, 1]",
                    from_ref="!<GroupTransform> {children: [!<ColorSpaceTransform> {src: linear, dst: Cineon}, "
                             "!<CDLTransform> {slope: [1.02, 1, 0.98], offset: [0, 0, 0], power: [1, 1, 1], sat: 0.95}, "
                             "!<ColorSpaceTransform> {src: Cineon, dst: rec709}]}"))

    header = """ocio_profile_version: 1

# Show config (v1) layered on nuke-default. Context variables:
#   SEQ / SHOT select the per-shot grade folder and the CCC id; defaults below.
#   Try:  SHOT=sh020 ociocheck --iconfig config.ocio   (or SEQ=sq02 SHOT=sh030)
environment:
  SEQ: sq01
  SHOT: sh010
search_path: "luts:looks:shots/${SEQ}/${SHOT}"
strictparsing: true
luma: [0.2126, 0.7152, 0.0722]
description: Show "BANDTEST" v1 config built on nuke-default

roles:
  color_picking: sRGB
  color_timing: show_log
  compositing_log: Cineon
  data: raw
  default: raw
  matte_paint: sRGB
  reference: linear
  scene_linear: linear
  texture_paint: sRGB

displays:
  default:
    - !<View> {name: None, colorspace: raw}
    - !<View> {name: sRGB, colorspace: sRGB}
    - !<View> {name: rec709, colorspace: rec709}
    - !<View> {name: rec1886, colorspace: Gamma2.4}
    - !<View> {name: Show sRGB, colorspace: sRGB, looks: "show_cdl, shot_grade"}
    - !<View> {name: Show Film, colorspace: sRGB, looks: "+show_lut, +shot_ccc"}
  review:
    - !<View> {name: Show rec709, colorspace: rec709, looks: "show_cdl, shot_grade"}
    - !<View> {name: editorial, colorspace: editorial_rec709}
    - !<View> {name: None, colorspace: raw}
  client:
    - !<View> {name: Gamma2.2, colorspace: Gamma2.2}
    - !<View> {name: None, colorspace: raw}

active_displays: [default, review]
active_views: [Show sRGB, Show rec709, Show Film, sRGB, rec709, rec1886, editorial, None]

looks:
  - !<Look>
    name: show_cdl
    process_space: Cineon
    transform: !<CDLTransform> {slope: [1.08, 1, 0.95], offset: [0.004, 0, -0.004], power: [1, 1, 1.03], sat: 1.1}

  - !<Look>
    name: shot_grade
    process_space: AlexaV3LogC
    transform: !<FileTransform> {src: shot_grade.cc, interpolation: linear}

  - !<Look>
    name: shot_ccc
    process_space: show_log
    transform: !<FileTransform> {src: grades.ccc, cccid: $SHOT, interpolation: linear}

  - !<Look>
    name: show_lut
    process_space: Cineon
    transform: !<FileTransform> {src: show_look.cube, interpolation: linear}
    inverse_transform: !<FileTransform> {src: show_look.cube, interpolation: linear, direction: inverse}

colorspaces:
"""
    with open(os.path.join(d, "config.ocio"), "w") as f:
        f.write(header)
        f.write("\n".join(nuke_colorspaces() + extra))


if __name__ == "__main__":
    make_nuke_default()
    make_show_v1()
