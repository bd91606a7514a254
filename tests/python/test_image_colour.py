# SPDX-License-Identifier: BSD-3-Clause
"""Images say what they are: `bandlight apply` (and Python's apply) decode
sRGB-encoded files and convert tagged primaries to the working space and
back, refuse what they cannot convert, and say what they assumed. Files
are written here by OpenImageIO with each tag, and untagged."""

import numpy as np
import OpenImageIO as oiio
import pytest

import bandlight
from conftest import cli_error, run_cli

REC709 = (0.64, 0.33, 0.30, 0.60, 0.15, 0.06, 0.3127, 0.3290)


def srgb_decode(v):
    """IEC 61966-2-1, written out independently of OpenColorIO."""
    v = np.asarray(v, np.float64)
    return np.where(v <= 0.04045, v / 12.92, ((v + 0.055) / 1.055) ** 2.4)


def srgb_encode(v):
    v = np.asarray(v, np.float64)
    return np.where(v <= 0.0031308, v * 12.92, 1.055 * np.abs(v) ** (1 / 2.4) - 0.055)


def rec709_to_acescg():
    # Bradford between the whites, as the ACES configs and bandlight's own do.
    m709, map1 = bandlight.rgb_to_xyz_matrix("rec709"), bandlight.rgb_to_xyz_matrix("acescg")
    cat = bandlight.adaptation_matrix(m709 @ np.ones(3), map1 @ np.ones(3), "bradford")
    return np.linalg.inv(map1) @ cat @ m709


def write(path, px, pixel_type="float", attributes=()):
    h, w, n = px.shape
    spec = oiio.ImageSpec(w, h, n, pixel_type)
    spec.channelnames = ("R", "G", "B", "A")[:n]
    for a in attributes:
        spec.attribute(*a)
    out = oiio.ImageOutput.create(str(path))
    assert out.open(str(path), spec), oiio.geterror()
    assert out.write_image(np.ascontiguousarray(px, np.float32))
    out.close()


def read(path, pixel_type="float"):
    i = oiio.ImageInput.open(str(path))
    px = i.read_image(pixel_type)
    i.close()
    return px


def test_an_srgb_png_is_decoded_relit_and_encoded_within_one_code_value(tmp_path):
    rng = np.random.default_rng(5)
    codes = rng.integers(0, 256, (32, 48, 3)).astype(np.uint8)
    write(tmp_path / "photo.png", codes / 255.0, "uint8")
    p = run_cli("apply", tmp_path / "photo.png", tmp_path / "out.png", "--from", "A", "--to", "D65",
                "--method", "bradford")
    assert "sRGB-encoded Rec.709" in p.stderr and "converted to linear ACEScg" in p.stderr
    out = read(tmp_path / "out.png", "uint8").astype(np.float64)
    # The reference: decode, Rec.709 → ACEScg, the Bradford look's matrix,
    # back, encode.
    m = bandlight.illuminant_change_matrix("A", "D65", "bradford", working_space="acescg")
    to = rec709_to_acescg()
    lin = srgb_decode(codes / 255.0) @ (np.linalg.inv(to) @ m @ to).T
    ref = srgb_encode(lin) * 255.0
    unclipped = np.all((ref >= 0.0) & (ref <= 255.0), axis=-1)
    assert unclipped.mean() > 0.5
    assert np.abs(out - ref)[unclipped].max() <= 1.0
    # Clipped pixels are clipped, not wrapped, and a note counts them.
    np.testing.assert_array_equal(out[~unclipped], np.clip(np.round(ref[~unclipped]), 0, 255))
    assert "pixels left 0-1 and are clipped" in p.stderr
    # Treated as ACEScg code values (the old behaviour) the result is far off.
    wrong = np.clip((codes / 255.0) @ m.T * 255.0, 0, 255)
    assert np.abs(wrong - ref)[unclipped].max() > 20


@pytest.mark.parametrize("attributes", [
    [("chromaticities", oiio.TypeDesc("float[8]"), REC709)],
    [("colorInteropID", "lin_rec709_scene")],
    [("colorInteropID", "lin_rec709_scene"), ("chromaticities", oiio.TypeDesc("float[8]"), REC709)],
])
def test_a_rec709_exr_is_converted_never_taken_as_acescg(tmp_path, attributes):
    rng = np.random.default_rng(6)
    px = rng.uniform(0.0, 8.0, (8, 16, 4)).astype(np.float32)
    write(tmp_path / "rec709.exr", px, attributes=attributes)
    p = run_cli("apply", tmp_path / "rec709.exr", tmp_path / "out.exr", "--from", "A", "--to", "D65")
    assert "linear Rec.709" in p.stderr
    out = read(tmp_path / "out.exr")
    m = bandlight.illuminant_change_matrix("A", "D65", "bradford", working_space="acescg")
    to = rec709_to_acescg()
    ref = px[..., :3].astype(np.float64) @ (np.linalg.inv(to) @ m @ to).T
    np.testing.assert_allclose(out[..., :3], ref, rtol=2e-5, atol=1e-6)
    np.testing.assert_array_equal(out[..., 3], px[..., 3])
    # The module's apply reads the same tags.
    with pytest.warns(bandlight.NoteWarning, match="Rec.709"):
        bandlight.apply(tmp_path / "rec709.exr", tmp_path / "py.exr", src="A", dst="D65")
    np.testing.assert_array_equal(read(tmp_path / "py.exr"), out)
    # --colorspace says otherwise: taken as ACEScg, as the user says.
    run_cli("apply", tmp_path / "rec709.exr", tmp_path / "as_acescg.exr", "--from", "A", "--to",
            "D65", "--colorspace", "acescg")
    np.testing.assert_allclose(read(tmp_path / "as_acescg.exr")[..., :3],
                               px[..., :3].astype(np.float64) @ m.T, rtol=2e-6, atol=1e-6)


def test_a_look_converts_a_tagged_image_to_scene_linear(tmp_path):
    rng = np.random.default_rng(7)
    px = rng.uniform(0.0, 4.0, (8, 16, 3)).astype(np.float32)
    write(tmp_path / "rec709.exr", px, attributes=[("colorInteropID", "lin_rec709_scene")])
    bandlight.config(tmp_path / "config", illuminants="A,D65", methods=["bradford"])
    run_cli("apply", tmp_path / "rec709.exr", tmp_path / "look.exr", "--look", "bradford_A_to_D65",
            "--config", tmp_path / "config")
    run_cli("apply", tmp_path / "rec709.exr", tmp_path / "method.exr", "--from", "A", "--to", "D65")
    np.testing.assert_allclose(read(tmp_path / "look.exr"), read(tmp_path / "method.exr"),
                               rtol=1e-6, atol=1e-6)


def test_untagged_float_images_are_taken_as_the_working_space_with_a_note(tmp_path):
    px = np.full((4, 4, 3), 0.5, np.float32)
    write(tmp_path / "plain.exr", px)
    p = run_cli("apply", tmp_path / "plain.exr", tmp_path / "out.exr", "--from", "A", "--to", "D65")
    assert "names no colour space: taken as linear ACEScg (say otherwise with --colorspace)" in p.stderr
    m = bandlight.illuminant_change_matrix("A", "D65", "bradford", working_space="acescg")
    np.testing.assert_allclose(read(tmp_path / "out.exr"), px @ m.T, rtol=2e-6)


def test_what_cannot_be_converted_is_refused_with_one_line(tmp_path):
    px = np.full((2, 2, 3), 0.5, np.float32)
    write(tmp_path / "log.png", px, "uint8", attributes=[("oiio:ColorSpace", "ARRI LogC")])
    err = cli_error("apply", tmp_path / "log.png", tmp_path / "o.png", "--from", "A", "--to", "D65")
    assert "log.png: has oiio:ColorSpace 'ARRI LogC'" in err and "--colorspace" in err
    assert "--working-space" in err
    write(tmp_path / "id.exr", px, attributes=[("colorInteropID", "logc4_awg4_scene")])
    err = cli_error("apply", tmp_path / "id.exr", tmp_path / "o.exr", "--from", "A", "--to", "D65")
    assert "id.exr: has colorInteropID 'logc4_awg4_scene'" in err
    write(tmp_path / "lies.exr", px, attributes=[("colorInteropID", "lin_ap1_scene"),
                                                 ("chromaticities", oiio.TypeDesc("float[8]"),
                                                  REC709)])
    err = cli_error("apply", tmp_path / "lies.exr", tmp_path / "o.exr", "--from", "A", "--to", "D65")
    assert "says it is linear ACEScg (colorInteropID lin_ap1_scene) and linear Rec.709" in err
    write(tmp_path / "hdr.exr", px)
    err = cli_error("apply", tmp_path / "hdr.exr", tmp_path / "o.png", "--from", "A", "--to", "D65")
    assert "o.png: a display-referred format" in err and "write an EXR" in err
    assert not any((tmp_path / n).exists() for n in ("o.exr", "o.png"))
    with pytest.raises(ValueError, match="colorspace.*working_space"):
        bandlight.apply(tmp_path / "log.png", tmp_path / "o.png", src="A", dst="D65")


def test_a_gamma_png_is_decoded_with_its_gamma(tmp_path):
    rng = np.random.default_rng(9)
    codes = rng.integers(0, 256, (8, 8, 3)).astype(np.uint8)
    write(tmp_path / "g.png", codes / 255.0, "uint8", attributes=[("oiio:ColorSpace", "Gamma1.8")])
    p = run_cli("apply", tmp_path / "g.png", tmp_path / "o.png", "--from", "A", "--to", "D65",
                "--method", "none")
    assert "gamma 1.8-encoded Rec.709" in p.stderr
    np.testing.assert_array_equal(read(tmp_path / "o.png", "uint8"), codes)


def test_sixteen_bit_tiff_and_an_srgb_override(tmp_path):
    rng = np.random.default_rng(8)
    codes = rng.uniform(0.0, 1.0, (8, 8, 3))
    write(tmp_path / "scan.tif", codes, "uint16")
    run_cli("apply", tmp_path / "scan.tif", tmp_path / "none.tif", "--from", "A", "--to", "D65",
            "--method", "none")
    # `none` through decode, ACEScg and back: the same code values.
    assert np.abs(read(tmp_path / "none.tif") - read(tmp_path / "scan.tif")).max() <= 1.01 / 65535
    # A float EXR holding sRGB code values, said so.
    write(tmp_path / "codes.exr", codes.astype(np.float32))
    run_cli("apply", tmp_path / "codes.exr", tmp_path / "codes_out.exr", "--from", "A", "--to",
            "D65", "--colorspace", "srgb")
    m = bandlight.illuminant_change_matrix("A", "D65", "bradford", working_space="acescg")
    to = rec709_to_acescg()
    ref = srgb_encode(srgb_decode(codes) @ (np.linalg.inv(to) @ m @ to).T)
    # OCIO's sRGB curve (ExponentWithLinear 2.4, 0.055, as the ACES configs
    # define it) is C1-continuous; IEC 61966-2-1's written-out toe differs
    # from it by up to 1e-4 near the break.
    np.testing.assert_allclose(read(tmp_path / "codes_out.exr"), ref, rtol=2e-6, atol=2e-4)
