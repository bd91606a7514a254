#!/usr/bin/python3
"""Writes aces-studio-v2.1/ : ACES studio/cg-config style config for OCIO 2.1 (builtins only, no LUT files
except one CLF look that exercises search_path in a v2 config)."""
import os, sys
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from colormath import *

# The folder to write into: the first argument (default: beside this folder).
ROOT = sys.argv[1] if len(sys.argv) > 1 else os.path.dirname(os.path.dirname(os.path.abspath(__file__)))


def to_ap0(prim, white):
    """linear RGB (prim, white) -> ACES2065-1, Bradford CAT white -> ACES white."""
    return mmul(minv(rgb_to_xyz(AP0, ACES_WHITE)), mmul(cat_bradford(white, ACES_WHITE), rgb_to_xyz(prim, white)))


def main():
    d = os.path.join(ROOT, "aces-studio-v2.1")
    os.makedirs(os.path.join(d, "luts"), exist_ok=True)
    m709 = fmt_m44(to_ap0(REC709, D65))
    m2020 = fmt_m44(to_ap0(REC2020, D65))
    mp3 = fmt_m44(to_ap0(P3, D65))

    # A small CLF look (Academy/ASC Common LUT Format) in ACEScct: a tiny exposure/contrast trim.
    with open(os.path.join(d, "luts", "show_trim.clf"), "w") as f:
        f.write("""<?xml version="1.0" encoding="UTF-8"?>
<ProcessList compCLFversion="3" id="show_trim_v001">
    <Description>Show trim: ACEScct contrast 1.08 about 0.4135884, slight warm offset</Description>
    <InputDescriptor>ACEScct</InputDescriptor>
    <OutputDescriptor>ACEScct</OutputDescriptor>
    <ASC_CDL id="trim" inBitDepth="32f" outBitDepth="32f" style="FwdNoClamp">
        <SOPNode>
            <Slope>1.08 1.08 1.08</Slope>
            <Offset>-0.029 -0.033 -0.037</Offset>
            <Power>1.0 1.0 1.0</Power>
        </SOPNode>
        <SatNode>
            <Saturation>1.05</Saturation>
        </SatNode>
    </ASC_CDL>
</ProcessList>
""")

    cfg = f"""ocio_profile_version: 2.1

environment:
  {{}}
search_path: luts
strictparsing: true
family_separator: /
luma: [0.2126, 0.7152, 0.0722]
name: studio-config-style_aces-v1.3_ocio-v2.1
description: |
  Academy Color Encoding System - Studio Config style [COLORSPACES v1.0.0] [ACES v1.3] [OCIO v2.1]
  Hand-written test config in the structure of OCIO-Config-ACES studio-config-v1.0.0 / cg-config-v1.0.0,
  using only BuiltinTransform styles known to OCIO 2.1.2.

roles:
  aces_interchange: ACES2065-1
  cie_xyz_d65_interchange: CIE-XYZ-D65
  color_picking: sRGB - Texture
  color_timing: ACEScct
  compositing_log: ACEScct
  data: Raw
  matte_paint: ACEScct
  scene_linear: ACEScg
  texture_paint: sRGB - Texture

file_rules:
  - !<Rule> {{name: OpenEXR, colorspace: ACEScg, pattern: "*", extension: exr}}
  - !<Rule> {{name: Textures, colorspace: sRGB - Texture, pattern: "*tex*", extension: "[pPjJ][nNpP][gG]"}}
  - !<Rule> {{name: ColorSpaceNamePathSearch}}
  - !<Rule> {{name: Default, colorspace: ACES2065-1}}

viewing_rules:
  - !<Rule> {{name: Data, colorspaces: [Raw]}}
  - !<Rule> {{name: Scene-linear, encodings: [scene-linear]}}

shared_views:
  - !<View> {{name: ACES 1.0 - SDR Video, view_transform: ACES 1.0 - SDR Video, display_colorspace: <USE_DISPLAY_NAME>}}
  - !<View> {{name: ACES 1.0 - SDR Video (D60 sim on D65), view_transform: ACES 1.0 - SDR Video (D60 sim on D65), display_colorspace: <USE_DISPLAY_NAME>}}
  - !<View> {{name: ACES 1.1 - SDR Video (P3 lim), view_transform: ACES 1.1 - SDR Video (P3 lim), display_colorspace: <USE_DISPLAY_NAME>}}
  - !<View> {{name: ACES 1.1 - HDR Video (1000 nits & Rec.2020 lim), view_transform: ACES 1.1 - HDR Video (1000 nits & Rec.2020 lim), display_colorspace: <USE_DISPLAY_NAME>}}
  - !<View> {{name: ACES 1.0 - SDR Video + RGC, view_transform: ACES 1.0 - SDR Video, display_colorspace: <USE_DISPLAY_NAME>, looks: ACES 1.3 Reference Gamut Compression}}
  - !<View> {{name: Show Trim, view_transform: ACES 1.0 - SDR Video, display_colorspace: <USE_DISPLAY_NAME>, looks: +Show Trim, rule: Scene-linear}}
  - !<View> {{name: Un-tone-mapped, view_transform: Un-tone-mapped, display_colorspace: <USE_DISPLAY_NAME>}}

displays:
  sRGB - Display:
    - !<View> {{name: Raw, colorspace: Raw, rule: Data}}
    - !<Views> [ACES 1.0 - SDR Video, ACES 1.0 - SDR Video + RGC, Show Trim, Un-tone-mapped]
  Rec.1886 Rec.709 - Display:
    - !<View> {{name: Raw, colorspace: Raw}}
    - !<Views> [ACES 1.0 - SDR Video, ACES 1.0 - SDR Video (D60 sim on D65), Un-tone-mapped]
  P3-D65 - Display:
    - !<View> {{name: Raw, colorspace: Raw}}
    - !<Views> [ACES 1.0 - SDR Video, ACES 1.1 - SDR Video (P3 lim), Un-tone-mapped]
  Rec.2100-PQ - Display:
    - !<View> {{name: Raw, colorspace: Raw}}
    - !<Views> [ACES 1.1 - HDR Video (1000 nits & Rec.2020 lim), Un-tone-mapped]
  Gamma 2.2 Rec.709 - Display:
    - !<View> {{name: Raw, colorspace: Raw}}
    - !<Views> [ACES 1.0 - SDR Video, Un-tone-mapped]

active_displays: [sRGB - Display, Rec.1886 Rec.709 - Display, P3-D65 - Display, Rec.2100-PQ - Display]
active_views: [ACES 1.0 - SDR Video, ACES 1.0 - SDR Video (D60 sim on D65), ACES 1.1 - SDR Video (P3 lim), ACES 1.1 - HDR Video (1000 nits & Rec.2020 lim), Show Trim, Un-tone-mapped, Raw]
inactive_colorspaces: [CIE-XYZ-D65, Gamma 2.2 Rec.709 - Display, ADX10]

default_view_transform: Un-tone-mapped

looks:
  - !<Look>
    name: ACES 1.3 Reference Gamut Compression
    process_space: ACES2065-1
    description: |
      LMT (applied in ACES2065-1) to compress scene-referred values from common cameras into the AP1 gamut
    transform: !<BuiltinTransform> {{style: ACES-LMT - ACES 1.3 Reference Gamut Compression}}

  - !<Look>
    name: Blue Light Artifact Fix
    process_space: ACES2065-1
    description: LMT for desaturating blue hues to reduce clipping artifacts
    transform: !<BuiltinTransform> {{style: ACES-LMT - BLUE_LIGHT_ARTIFACT_FIX}}

  - !<Look>
    name: Show Trim
    process_space: ACEScct
    description: show trim stored as CLF, found through search_path
    transform: !<FileTransform> {{src: show_trim.clf}}

view_transforms:
  - !<ViewTransform>
    name: ACES 1.0 - SDR Video
    description: Component of ACES Output Transforms for SDR D65 video
    from_scene_reference: !<BuiltinTransform> {{style: ACES-OUTPUT - ACES2065-1_to_CIE-XYZ-D65 - SDR-VIDEO_1.0}}

  - !<ViewTransform>
    name: ACES 1.0 - SDR Video (D60 sim on D65)
    description: Component of ACES Output Transforms for SDR D65 video simulating D60 white
    from_scene_reference: !<BuiltinTransform> {{style: ACES-OUTPUT - ACES2065-1_to_CIE-XYZ-D65 - SDR-VIDEO-D60sim-D65_1.0}}

  - !<ViewTransform>
    name: ACES 1.1 - SDR Video (P3 lim)
    description: Component of ACES Output Transforms for SDR D65 video
    from_scene_reference: !<BuiltinTransform> {{style: ACES-OUTPUT - ACES2065-1_to_CIE-XYZ-D65 - SDR-VIDEO-P3lim_1.1}}

  - !<ViewTransform>
    name: ACES 1.1 - HDR Video (1000 nits & Rec.2020 lim)
    description: Component of ACES Output Transforms for 1000 nit HDR D65 video
    from_scene_reference: !<BuiltinTransform> {{style: ACES-OUTPUT - ACES2065-1_to_CIE-XYZ-D65 - HDR-VIDEO-1000nit-15nit-REC2020lim_1.1}}

  - !<ViewTransform>
    name: Un-tone-mapped
    description: "Un-tone-mapped: ACES2065-1 -> CIE-XYZ-D65 (Bradford)"
    from_scene_reference: !<BuiltinTransform> {{style: UTILITY - ACES-AP0_to_CIE-XYZ-D65_BFD}}

display_colorspaces:
  - !<ColorSpace>
    name: CIE-XYZ-D65
    aliases: [cie_xyz_d65]
    family: ""
    equalitygroup: ""
    bitdepth: 32f
    description: The "CIE XYZ (D65)" display connection colorspace.
    isdata: false
    allocation: uniform

  - !<ColorSpace>
    name: sRGB - Display
    aliases: [srgb_display]
    family: Display
    equalitygroup: ""
    bitdepth: 32f
    description: Convert CIE XYZ (D65 white) to sRGB (piecewise EOTF)
    isdata: false
    categories: [file-io]
    encoding: sdr-video
    allocation: uniform
    from_display_reference: !<BuiltinTransform> {{style: DISPLAY - CIE-XYZ-D65_to_sRGB}}

  - !<ColorSpace>
    name: Rec.1886 Rec.709 - Display
    aliases: [rec1886_rec709_display]
    family: Display
    equalitygroup: ""
    bitdepth: 32f
    description: Convert CIE XYZ (D65 white) to Rec.1886/Rec.709 (HD video)
    isdata: false
    categories: [file-io]
    encoding: sdr-video
    allocation: uniform
    from_display_reference: !<BuiltinTransform> {{style: DISPLAY - CIE-XYZ-D65_to_REC.1886-REC.709}}

  - !<ColorSpace>
    name: P3-D65 - Display
    aliases: [g26_p3d65_display]
    family: Display
    equalitygroup: ""
    bitdepth: 32f
    description: Convert CIE XYZ (D65 white) to Gamma 2.6, P3-D65
    isdata: false
    categories: [file-io]
    encoding: sdr-video
    allocation: uniform
    from_display_reference: !<BuiltinTransform> {{style: DISPLAY - CIE-XYZ-D65_to_G2.6-P3-D65}}

  - !<ColorSpace>
    name: Rec.2100-PQ - Display
    aliases: [rec2100_pq_display]
    family: Display
    equalitygroup: ""
    bitdepth: 32f
    description: Convert CIE XYZ (D65 white) to Rec.2100-PQ
    isdata: false
    categories: [file-io]
    encoding: hdr-video
    allocation: uniform
    from_display_reference: !<BuiltinTransform> {{style: DISPLAY - CIE-XYZ-D65_to_REC.2100-PQ}}

  - !<ColorSpace>
    name: Gamma 2.2 Rec.709 - Display
    aliases: [g22_rec709_display]
    family: Display
    equalitygroup: ""
    bitdepth: 32f
    description: Convert CIE XYZ (D65 white) to Gamma2.2, Rec.709
    isdata: false
    categories: [file-io]
    encoding: sdr-video
    allocation: uniform
    from_display_reference: !<BuiltinTransform> {{style: DISPLAY - CIE-XYZ-D65_to_G2.2-REC.709}}

colorspaces:
  - !<ColorSpace>
    name: ACES2065-1
    aliases: [aces2065_1, ACES - ACES2065-1, lin_ap0]
    family: ACES
    equalitygroup: ""
    bitdepth: 32f
    description: The "Academy Color Encoding System" reference colorspace.
    isdata: false
    categories: [file-io]
    encoding: scene-linear
    allocation: uniform

  - !<ColorSpace>
    name: ACEScc
    aliases: [ACES - ACEScc, acescc_ap1]
    family: ACES
    equalitygroup: ""
    bitdepth: 32f
    description: Convert ACEScc to ACES2065-1
    isdata: false
    categories: [file-io]
    encoding: log
    allocation: uniform
    to_scene_reference: !<BuiltinTransform> {{style: ACEScc_to_ACES2065-1}}

  - !<ColorSpace>
    name: ACEScct
    aliases: [ACES - ACEScct, acescct_ap1]
    family: ACES
    equalitygroup: ""
    bitdepth: 32f
    description: Convert ACEScct to ACES2065-1
    isdata: false
    categories: [file-io, working-space]
    encoding: log
    allocation: uniform
    to_scene_reference: !<BuiltinTransform> {{style: ACEScct_to_ACES2065-1}}

  - !<ColorSpace>
    name: ACEScg
    aliases: [ACES - ACEScg, lin_ap1]
    family: ACES
    equalitygroup: ""
    bitdepth: 32f
    description: Convert ACEScg to ACES2065-1
    isdata: false
    categories: [file-io, working-space]
    encoding: scene-linear
    allocation: uniform
    to_scene_reference: !<BuiltinTransform> {{style: ACEScg_to_ACES2065-1}}

  - !<ColorSpace>
    name: ADX10
    aliases: [Input - ADX - ADX10]
    family: ACES
    equalitygroup: ""
    bitdepth: 32f
    description: Convert ADX10 to ACES2065-1
    isdata: false
    categories: [file-io]
    encoding: log
    allocation: uniform
    to_scene_reference: !<BuiltinTransform> {{style: ADX10_to_ACES2065-1}}

  - !<ColorSpace>
    name: ARRI LogC3 (EI800)
    aliases: [arri_logc3_ei800, Input - ARRI - V3 LogC (EI800) - Wide Gamut]
    family: Input/ARRI
    equalitygroup: ""
    bitdepth: 32f
    description: Convert ARRI ALEXA LogC (EI800) ALEXA Wide Gamut to ACES2065-1
    isdata: false
    categories: [file-io]
    encoding: log
    allocation: uniform
    to_scene_reference: !<BuiltinTransform> {{style: ARRI_ALEXA-LOGC-EI800-AWG_to_ACES2065-1}}

  - !<ColorSpace>
    name: S-Log3 S-Gamut3.Cine
    aliases: [slog3_sgamutcine, Input - Sony - S-Log3 - S-Gamut3.Cine]
    family: Input/Sony
    equalitygroup: ""
    bitdepth: 32f
    description: Convert Sony S-Log3 S-Gamut3.Cine to ACES2065-1
    isdata: false
    categories: [file-io]
    encoding: log
    allocation: uniform
    to_scene_reference: !<BuiltinTransform> {{style: SONY_SLOG3-SGAMUT3.CINE_to_ACES2065-1}}

  - !<ColorSpace>
    name: Log3G10 REDWideGamutRGB
    aliases: [log3g10_rwg, Input - RED - Log3G10 - REDWideGamutRGB]
    family: Input/RED
    equalitygroup: ""
    bitdepth: 32f
    description: Convert RED Log3G10 RED Wide Gamut to ACES2065-1
    isdata: false
    categories: [file-io]
    encoding: log
    allocation: uniform
    to_scene_reference: !<BuiltinTransform> {{style: RED_LOG3G10-RWG_to_ACES2065-1}}

  - !<ColorSpace>
    name: V-Log V-Gamut
    aliases: [vlog_vgamut, Input - Panasonic - V-Log - V-Gamut]
    family: Input/Panasonic
    equalitygroup: ""
    bitdepth: 32f
    description: Convert Panasonic Varicam V-Log V-Gamut to ACES2065-1
    isdata: false
    categories: [file-io]
    encoding: log
    allocation: uniform
    to_scene_reference: !<BuiltinTransform> {{style: PANASONIC_VLOG-VGAMUT_to_ACES2065-1}}

  - !<ColorSpace>
    name: Linear Rec.709 (sRGB)
    aliases: [lin_rec709_srgb, Utility - Linear - Rec.709, lin_rec709, lin_srgb]
    family: Utility/Linear
    equalitygroup: ""
    bitdepth: 32f
    description: Convert ACES2065-1 to linear Rec.709 primaries, D65 white point
    isdata: false
    categories: [file-io, working-space]
    encoding: scene-linear
    allocation: uniform
    to_scene_reference: !<MatrixTransform> {{matrix: {m709}}}

  - !<ColorSpace>
    name: Linear P3-D65
    aliases: [lin_p3d65, Utility - Linear - P3-D65]
    family: Utility/Linear
    equalitygroup: ""
    bitdepth: 32f
    description: Convert ACES2065-1 to linear P3 primaries, D65 white point
    isdata: false
    categories: [file-io, working-space]
    encoding: scene-linear
    allocation: uniform
    to_scene_reference: !<MatrixTransform> {{matrix: {mp3}}}

  - !<ColorSpace>
    name: Linear Rec.2020
    aliases: [lin_rec2020, Utility - Linear - Rec.2020]
    family: Utility/Linear
    equalitygroup: ""
    bitdepth: 32f
    description: Convert ACES2065-1 to linear Rec.2020 primaries, D65 white point
    isdata: false
    categories: [file-io, working-space]
    encoding: scene-linear
    allocation: uniform
    to_scene_reference: !<MatrixTransform> {{matrix: {m2020}}}

  - !<ColorSpace>
    name: sRGB - Texture
    aliases: [srgb_tx, Utility - sRGB - Texture, srgb_texture, Input - Generic - sRGB - Texture]
    family: Utility
    equalitygroup: ""
    bitdepth: 32f
    description: Convert ACES2065-1 to sRGB
    isdata: false
    categories: [file-io]
    encoding: sdr-video
    allocation: uniform
    to_scene_reference: !<GroupTransform>
      name: sRGB Encoded Rec.709 (sRGB) to ACES2065-1
      children:
        - !<ExponentWithLinearTransform> {{gamma: 2.4, offset: 0.055}}
        - !<MatrixTransform> {{matrix: {m709}}}

  - !<ColorSpace>
    name: Gamma 2.2 Rec.709 - Texture
    aliases: [g22_rec709_tx, Utility - Gamma 2.2 - Rec.709 - Texture]
    family: Utility
    equalitygroup: ""
    bitdepth: 32f
    description: Convert ACES2065-1 to gamma 2.2 encoded Rec.709
    isdata: false
    categories: [file-io]
    encoding: sdr-video
    allocation: uniform
    to_scene_reference: !<GroupTransform>
      children:
        - !<ExponentTransform> {{value: 2.2, style: pass_thru}}
        - !<MatrixTransform> {{matrix: {m709}}}

  - !<ColorSpace>
    name: Raw
    aliases: [Utility - Raw, raw]
    family: Utility
    equalitygroup: ""
    bitdepth: 32f
    description: The utility "Raw" colorspace.
    isdata: true
    categories: [file-io]
    allocation: uniform

named_transforms:
  - !<NamedTransform>
    name: sRGB - Curve
    aliases: [srgb_crv]
    description: sRGB piecewise curve only (no primaries), as in later ACES configs
    family: Utility/Curves
    encoding: sdr-video
    inverse_transform: !<ExponentWithLinearTransform> {{gamma: 2.4, offset: 0.055}}

  - !<NamedTransform>
    name: ACEScct Curve
    aliases: [acescct_crv]
    family: Utility/Curves
    encoding: log
    inverse_transform: !<BuiltinTransform> {{style: CURVE - ACEScct-LOG_to_LINEAR}}
"""
    with open(os.path.join(d, "config.ocio"), "w") as f:
        f.write(cfg)


if __name__ == "__main__":
    main()
