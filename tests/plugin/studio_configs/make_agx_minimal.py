#!/usr/bin/python3
"""Writes agx-xyzE-ref/ (reference = Linear CIE-XYZ I-E, scene_linear = Linear Rec.709, no interchange roles)
and minimal-srgb-v2/ (no interchange roles, no XYZ, scene_linear lin_rec709, only an sRGB display space)."""
import math, os, sys
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from colormath import *

# The folder to write into: the first argument (default: beside this folder).
ROOT = sys.argv[1] if len(sys.argv) > 1 else os.path.dirname(os.path.dirname(os.path.abspath(__file__)))

# AgX inset matrix (Rec.2020 domain) as published with Troy Sobotka's AgX / Blender 4.0
INSET = [[0.856627153315983, 0.0951212405381588, 0.0482516061458583],
         [0.137318972929847, 0.761241990602591, 0.101439036467562],
         [0.11189821299995, 0.0767994186031903, 0.811302368396859]]
OUTSET = minv(INSET)
MIN_EV, MAX_EV = -12.47393, 4.026069  # log2 range about 0.18 (as in AgX)


def agx_sigmoid(x):
    """6th-order polynomial approximation of the AgX default-contrast sigmoid (log in, ~2.2-encoded out)."""
    x = min(max(x, 0.0), 1.0)
    x2 = x * x
    x4 = x2 * x2
    return 15.5 * x4 * x2 - 40.14 * x4 * x + 31.96 * x4 - 6.868 * x2 * x + 0.4298 * x2 + 0.1191 * x - 0.00232


def main_agx():
    d = os.path.join(ROOT, "agx-xyzE-ref")
    lut = os.path.join(d, "luts")
    os.makedirs(lut, exist_ok=True)

    xyz709 = rgb_to_xyz(REC709, D65)
    xyz2020 = rgb_to_xyz(REC2020, D65)
    xyzp3 = rgb_to_xyz(P3, D65)
    d65_to_e = cat_bradford(D65, E_WHITE)
    e_to_d65 = minv(d65_to_e)
    r2020_to_709 = mmul(minv(xyz709), xyz2020)

    # 3D LUT: AgX Log (inset Rec.2020, log2-allocated) -> display-linear Rec.709 (clipped)
    def agx_base(r, g, b):
        s = [max(agx_sigmoid(c), 0.0) ** 2.2 for c in (r, g, b)]
        o = mvec(OUTSET, s)
        o = mvec(r2020_to_709, o)
        return [min(max(c, 0.0), 1.0) for c in o]
    write_cube3d(os.path.join(lut, "AgX_Base_Rec709_linear.cube"), agx_base, 37,
                 "AgX base (approx): AgX Log -> display-linear Rec.709")
    # 1D sigmoid for the 'AgX Log' punchy/contrast look (log in, log out)
    P = (math.log2(0.18) - MIN_EV) / (MAX_EV - MIN_EV)  # 0.18 in AgX Log (~0.606), kept fixed
    K = 1.2

    def punchy(x):  # monotonic S-curve, 0->0, P->P, 1->1, slope K/tanh(K) at P
        x = min(max(x, 0.0), 1.0)
        if x < P:
            return P - P * math.tanh((P - x) * K / P) / math.tanh(K)
        return P + (1 - P) * math.tanh((x - P) * K / (1 - P)) / math.tanh(K)
    write_spi1d(os.path.join(lut, "agx_punchy_curve.spi1d"), punchy, 0.0, 1.0, 1024)

    m_709_to_ref = fmt_m44(mmul(d65_to_e, xyz709))
    m_2020_to_ref = fmt_m44(mmul(d65_to_e, xyz2020))
    m_p3_to_ref = fmt_m44(mmul(d65_to_e, xyzp3))
    m_xyzd65_to_ref = fmt_m44(d65_to_e)
    m_ref_to_709 = fmt_m44(mmul(minv(xyz709), e_to_d65))
    m_ref_to_p3 = fmt_m44(mmul(minv(xyzp3), e_to_d65))
    m_709_to_ref_display = m_709_to_ref
    m_inset = fmt_m44(INSET)
    lum709 = fmt_m44([[0.2126, 0.7152, 0.0722]] * 3)

    cfg = f"""ocio_profile_version: 2

# AgX-style config (Blender 4.x AgX structure, approximated).
# Reference space is Linear CIE-XYZ I-E (XYZ with equal-energy white), NOT the working space.
# scene_linear = Linear Rec.709, defined by a MatrixTransform from the reference.
# No aces_interchange / cie_xyz_d65_interchange roles: the working primaries are only identifiable
# through "Linear CIE-XYZ D65", "sRGB Encoded Rec.709" or the "sRGB - Display" colour space.
environment:
  {{}}
search_path: luts
strictparsing: true
luma: [0.2126, 0.7152, 0.0722]
name: agx-xyzE-reference
description: AgX-style test config whose reference space (Linear CIE-XYZ I-E) differs from scene_linear

roles:
  reference: Linear CIE-XYZ I-E
  scene_linear: Linear Rec.709
  rendering: Linear Rec.709
  default_float: Linear Rec.709
  default_byte: sRGB Encoded Rec.709
  default_sequencer: sRGB Encoded Rec.709
  color_picking: sRGB Encoded Rec.709
  texture_paint: Linear Rec.709
  matte_paint: Linear Rec.709
  color_timing: AgX Log
  compositing_log: AgX Log
  data: Non-Color
  default: Linear Rec.709

file_rules:
  - !<Rule> {{name: Default, colorspace: default}}

displays:
  sRGB:
    - !<View> {{name: Standard, view_transform: Standard, display_colorspace: sRGB - Display}}
    - !<View> {{name: AgX, view_transform: AgX Base, display_colorspace: sRGB - Display}}
    - !<View> {{name: AgX Punchy, view_transform: AgX Base, display_colorspace: sRGB - Display, looks: AgX - Punchy}}
    - !<View> {{name: AgX Log, colorspace: AgX Log}}
    - !<View> {{name: Raw, colorspace: Non-Color}}
  Display P3:
    - !<View> {{name: Standard, view_transform: Standard, display_colorspace: Display P3 - Display}}
    - !<View> {{name: AgX, view_transform: AgX Base, display_colorspace: Display P3 - Display}}
    - !<View> {{name: Raw, colorspace: Non-Color}}

active_displays: []
active_views: []

default_view_transform: Standard

looks:
  - !<Look>
    name: AgX - Punchy
    process_space: AgX Log
    description: punchier contrast + saturation in AgX Log
    transform: !<GroupTransform>
      children:
        - !<FileTransform> {{src: agx_punchy_curve.spi1d, interpolation: linear}}
        - !<CDLTransform> {{slope: [1, 1, 1], offset: [0, 0, 0], power: [1.035, 1.035, 1.035], sat: 1.4}}

  - !<Look>
    name: AgX - Greyscale
    process_space: Linear Rec.709
    transform: !<MatrixTransform> {{matrix: {lum709}}}

  - !<Look>
    name: AgX - High Contrast
    process_space: AgX Log
    transform: !<GradingPrimaryTransform>
      style: log
      contrast: {{rgb: [1, 1, 1], master: 1.3}}
      saturation: 1.1
      pivot: {{contrast: 0.2121212}}  # = AgX Log 0.606 (0.18 grey); log-style pivot p -> 0.5 + 0.5*p

view_transforms:
  - !<ViewTransform>
    name: Standard
    description: No tone mapping; scene XYZ-E passed to display XYZ-E
    from_scene_reference: !<BuiltinTransform> {{style: IDENTITY}}

  - !<ViewTransform>
    name: AgX Base
    description: AgX (approximate) - log2 allocation in inset Rec.2020 then a 3D LUT
    from_scene_reference: !<GroupTransform>
      children:
        - !<ColorSpaceTransform> {{src: Linear CIE-XYZ I-E, dst: AgX Log}}
        - !<FileTransform> {{src: AgX_Base_Rec709_linear.cube, interpolation: tetrahedral}}
        - !<MatrixTransform> {{matrix: {m_709_to_ref_display}}}

display_colorspaces:
  - !<ColorSpace>
    name: sRGB - Display
    family: Display
    equalitygroup: ""
    bitdepth: 32f
    description: sRGB IEC 61966-2-1 display (piecewise EOTF), Rec.709 primaries, D65
    isdata: false
    encoding: sdr-video
    allocation: uniform
    from_display_reference: !<GroupTransform>
      children:
        - !<MatrixTransform> {{matrix: {m_ref_to_709}}}
        - !<RangeTransform> {{min_in_value: 0, max_in_value: 1, min_out_value: 0, max_out_value: 1}}
        - !<ExponentWithLinearTransform> {{gamma: 2.4, offset: 0.055, direction: inverse}}

  - !<ColorSpace>
    name: Display P3 - Display
    family: Display
    equalitygroup: ""
    bitdepth: 32f
    description: Display P3 (P3 primaries, D65, sRGB piecewise EOTF)
    isdata: false
    encoding: sdr-video
    allocation: uniform
    from_display_reference: !<GroupTransform>
      children:
        - !<MatrixTransform> {{matrix: {m_ref_to_p3}}}
        - !<RangeTransform> {{min_in_value: 0, max_in_value: 1, min_out_value: 0, max_out_value: 1}}
        - !<ExponentWithLinearTransform> {{gamma: 2.4, offset: 0.055, direction: inverse}}

colorspaces:
  - !<ColorSpace>
    name: Linear CIE-XYZ I-E
    family: Chromaticity
    equalitygroup: ""
    bitdepth: 32f
    description: 1931 CIE XYZ with the equal-energy (E) white. Reference space of this config.
    isdata: false
    encoding: scene-linear
    allocation: lg2
    allocationvars: [-12.4739, 12.5261]

  - !<ColorSpace>
    name: Linear CIE-XYZ D65
    family: Chromaticity
    equalitygroup: ""
    bitdepth: 32f
    description: 1931 CIE XYZ, D65 white (Bradford from E). Deliberately NOT tagged cie_xyz_d65_interchange.
    isdata: false
    encoding: scene-linear
    to_scene_reference: !<MatrixTransform> {{matrix: {m_xyzd65_to_ref}}}

  - !<ColorSpace>
    name: Linear Rec.709
    family: Linear
    equalitygroup: ""
    bitdepth: 32f
    description: Linear BT.709 primaries, D65 white. Working space (scene_linear).
    isdata: false
    encoding: scene-linear
    to_scene_reference: !<MatrixTransform> {{matrix: {m_709_to_ref}}}

  - !<ColorSpace>
    name: Linear Rec.2020
    family: Linear
    equalitygroup: ""
    bitdepth: 32f
    description: Linear BT.2020 primaries, D65 white
    isdata: false
    encoding: scene-linear
    to_scene_reference: !<MatrixTransform> {{matrix: {m_2020_to_ref}}}

  - !<ColorSpace>
    name: Linear DCI-P3 D65
    family: Linear
    equalitygroup: ""
    bitdepth: 32f
    description: Linear P3 primaries, D65 white
    isdata: false
    encoding: scene-linear
    to_scene_reference: !<MatrixTransform> {{matrix: {m_p3_to_ref}}}

  - !<ColorSpace>
    name: sRGB Encoded Rec.709
    family: Utility
    equalitygroup: ""
    bitdepth: 32f
    description: sRGB piecewise encoded Rec.709 (texture / byte images)
    isdata: false
    encoding: sdr-video
    to_scene_reference: !<GroupTransform>
      children:
        - !<ExponentWithLinearTransform> {{gamma: 2.4, offset: 0.055}}
        - !<ColorSpaceTransform> {{src: Linear Rec.709, dst: Linear CIE-XYZ I-E}}

  - !<ColorSpace>
    name: AgX Log
    family: Log Encodings
    equalitygroup: ""
    bitdepth: 32f
    description: AgX log2 encoding of inset Rec.2020 (log2 range {MIN_EV} .. {MAX_EV} stops about 0.18)
    isdata: false
    encoding: log
    from_scene_reference: !<GroupTransform>
      children:
        - !<ColorSpaceTransform> {{src: Linear CIE-XYZ I-E, dst: Linear Rec.2020}}
        - !<RangeTransform> {{min_in_value: 0, min_out_value: 0}}
        - !<MatrixTransform> {{matrix: {m_inset}}}
        - !<AllocationTransform> {{allocation: lg2, vars: [{MIN_EV}, {MAX_EV}]}}

  - !<ColorSpace>
    name: Non-Color
    family: Data
    equalitygroup: ""
    bitdepth: 32f
    description: Generic data that is not color, will not apply any color transform (e.g. normal maps)
    isdata: true
"""
    with open(os.path.join(d, "config.ocio"), "w") as f:
        f.write(cfg)


def main_minimal():
    d = os.path.join(ROOT, "minimal-srgb-v2")
    os.makedirs(os.path.join(d, "luts"), exist_ok=True)
    # a generic log shaper LUT (lg2 -8..+8 stops around 0.18) that carries no primaries information
    write_spi1d(os.path.join(d, "luts", "log2_shaper.spi1d"),
                lambda x: 0.18 * 2.0 ** (x * 16.0 - 8.0), 0.0, 1.0, 4096)
    cfg = """ocio_profile_version: 2

# Minimal v2 config: no aces_interchange / cie_xyz_d65_interchange roles, no XYZ colour space.
# scene_linear is "lin_rec709"; the only thing that identifies its primaries is the "sRGB" colour space.
environment:
  {}
search_path: luts
strictparsing: true
luma: [0.2126, 0.7152, 0.0722]

roles:
  scene_linear: lin_rec709
  default: lin_rec709
  data: raw
  color_picking: sRGB
  compositing_log: log2_shaper
  color_timing: log2_shaper

file_rules:
  - !<Rule> {name: Default, colorspace: default}

displays:
  sRGB:
    - !<View> {name: Standard, colorspace: sRGB}
    - !<View> {name: Log, colorspace: log2_shaper}
    - !<View> {name: Raw, colorspace: raw}

active_displays: []
active_views: []

colorspaces:
  - !<ColorSpace>
    name: lin_rec709
    family: linear
    equalitygroup: ""
    bitdepth: 32f
    description: scene-linear working space (reference)
    isdata: false
    encoding: scene-linear
    allocation: lg2
    allocationvars: [-10, 8, 0.00390625]

  - !<ColorSpace>
    name: sRGB
    family: display
    equalitygroup: ""
    bitdepth: 32f
    description: sRGB piecewise curve (IEC 61966-2-1)
    isdata: false
    encoding: sdr-video
    from_scene_reference: !<ExponentWithLinearTransform> {gamma: 2.4, offset: 0.055, direction: inverse}

  - !<ColorSpace>
    name: log2_shaper
    family: log
    equalitygroup: ""
    bitdepth: 32f
    description: log2 shaper, 16 stops centred on 0.18 (LUT file)
    isdata: false
    encoding: log
    to_scene_reference: !<FileTransform> {src: log2_shaper.spi1d, interpolation: linear}

  - !<ColorSpace>
    name: raw
    family: data
    equalitygroup: ""
    bitdepth: 32f
    description: non-colour data
    isdata: true
"""
    with open(os.path.join(d, "config.ocio"), "w") as f:
        f.write(cfg)


if __name__ == "__main__":
    main_agx()
    main_minimal()
