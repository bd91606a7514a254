# SPDX-License-Identifier: BSD-3-Clause
"""Transforms are PyOpenColorIO's own objects, and they are the command's.

bandlight's extension returns OCIO::GroupTransformRcPtr; Debian's
PyOpenColorIO is a pybind11 module with the same internals ID
(v4, gcc, libstdc++, cxxabi1017) as Debian's pybind11-dev, so the two share
one type registry and the object arrives as PyOpenColorIO.GroupTransform:
no copy, no serialisation. These tests prove it in both directions.
"""

import json
import subprocess
import sys

import numpy as np
import OpenImageIO as oiio
import PyOpenColorIO as OCIO
import pytest

import bandlight
from conftest import acescg_spec, run_cli


def processor_matrix(transform):
    """The 3x3 a transform applies, measured through PyOpenColorIO alone."""
    cpu = OCIO.Config.CreateRaw().getProcessor(transform).getDefaultCPUProcessor()
    basis = np.eye(3, dtype=np.float32)
    cpu.applyRGB(basis)
    return basis.T.astype(np.float64)  # columns are the images of the basis vectors


def test_illuminant_change_is_a_pyopencolorio_group_transform():
    t = bandlight.illuminant_change("A", "D65", method="bradford", working_space="acescg")
    assert type(t) is OCIO.GroupTransform
    assert isinstance(t, OCIO.Transform)
    # Its parts are PyOpenColorIO types too: the +-1e16 guard, then the matrix.
    parts = list(t)
    assert [type(p) for p in parts] == [OCIO.RangeTransform, OCIO.MatrixTransform]
    assert parts[0].getMaxInValue() == pytest.approx(1e16)
    # The processor a raw config makes of it applies the library's matrix.
    m = bandlight.illuminant_change_matrix("A", "D65", "bradford", working_space="acescg")
    np.testing.assert_allclose(processor_matrix(t), m, rtol=0, atol=2e-7)
    # On white-balanced plates (the default) a neutral stays neutral; for lit
    # plates Bradford maps A's white in ACEScg (Y = 1, over the 380-780 nm the
    # methods integrate) exactly to D65's.
    np.testing.assert_allclose(m @ np.ones(3), np.ones(3), atol=1e-12)
    lit = bandlight.illuminant_change_matrix("A", "D65", "bradford", plates="lit")
    to_xyz = bandlight.rgb_to_xyz_matrix("acescg")
    white = {n: np.linalg.solve(to_xyz, bandlight.xyz(bandlight.illuminant(n).resampled(
        380, 5, 81)) / 100) for n in ("A", "D65")}
    np.testing.assert_allclose(lit @ white["A"], white["D65"], atol=1e-12)


def test_transform_is_a_live_pyopencolorio_object():
    # PyOpenColorIO edits it, serialises it and puts it into a config.
    t = bandlight.illuminant_change("A", "D65", "band3")
    t.appendTransform(OCIO.ExposureContrastTransform(exposure=1.0))
    assert len(t) == 3
    ctf = t.write("Color Transform Format", OCIO.Config.CreateRaw())
    assert "<Matrix" in ctf and "<ExposureContrast" in ctf
    config = OCIO.Config.CreateRaw()
    look = OCIO.Look(name="relight", processSpace="raw", transform=t)
    config.addLook(look)
    assert config.getLook("relight").getTransform() is not None


def test_pyopencolorio_objects_flow_back_into_bandlight():
    # A PyOpenColorIO.Processor goes into the C++ MeasureMatrix unchanged.
    t = bandlight.illuminant_change("F11", "D65", "cat02", working_space="rec2020")
    proc = OCIO.Config.CreateRaw().getProcessor(t)
    np.testing.assert_allclose(
        bandlight.measure_matrix(proc),
        bandlight.illuminant_change_matrix("F11", "D65", "cat02", working_space="rec2020"),
        atol=2e-7)


def test_types_are_shared_whatever_the_import_order():
    # A fresh interpreter that imports bandlight first (it imports
    # PyOpenColorIO itself before returning any transform).
    code = ("import bandlight\n"
            "t = bandlight.band_space()\n"
            "import PyOpenColorIO as OCIO\n"
            "assert type(t) is OCIO.GroupTransform, type(t)\n"
            "print(type(t).__module__, type(t).__name__)\n")
    p = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True)
    assert p.returncode == 0, p.stderr
    assert p.stdout.strip() == "PyOpenColorIO GroupTransform"


@pytest.mark.parametrize("method", ["none", "vonkries", "bradford", "cat02", "band3",
                                    "band3-wp", "band6", "fit3x3", "prefilter", "metamer"])
def test_linear_methods_match_the_commands_clf(tmp_path, method):
    # `bandlight lut` writes a linear method's CLF as the matrix itself.
    clf = tmp_path / f"{method}.clf"
    run_cli("lut", "--from", "A", "--to", "F11", "--method", method, "--format", "clf",
            "-o", clf)
    t = OCIO.FileTransform(src=str(clf), interpolation=OCIO.INTERP_TETRAHEDRAL)
    np.testing.assert_allclose(processor_matrix(t),
                               processor_matrix(bandlight.illuminant_change("A", "F11", method)),
                               rtol=0, atol=1e-6)


def write_exr(path, pixels):
    out = oiio.ImageOutput.create(str(path))
    h, w, c = pixels.shape
    assert out.open(str(path), acescg_spec(w, h, c)), oiio.geterror()
    assert out.write_image(pixels)
    out.close()


def read_exr(path):
    inp = oiio.ImageInput.open(str(path))
    assert inp, oiio.geterror()
    pixels = inp.read_image("float")
    inp.close()
    return pixels


def plate(height=24, width=32):
    """A small scene-linear plate: colours over five stops, some HDR values,
    a black and a few negatives (as out-of-gamut pixels have)."""
    rng = np.random.default_rng(14)
    px = rng.uniform(0.0, 1.0, (height, width, 3)) * 2.0 ** rng.uniform(-5, 3, (height, width, 1))
    px[0, 0] = 0.0
    px[0, 1] = [-0.01, 0.2, 0.5]
    px[0, 2] = [60000.0, 30000.0, 1000.0]
    return px.astype(np.float32)


@pytest.mark.parametrize("method", ["band3", "bradford", "upsample"])
def test_group_transform_applied_by_pyopencolorio_equals_bandlight_apply(tmp_path, method):
    src = tmp_path / "plate.exr"
    out = tmp_path / f"plate_{method}.exr"
    pixels = plate()
    write_exr(src, pixels)
    run_cli("apply", src, out, "--from", "A", "--to", "D65", "--method", method)
    by_cli = read_exr(out)

    t = bandlight.illuminant_change("A", "D65", method=method, working_space="acescg")
    by_ocio = pixels.copy()
    OCIO.Config.CreateRaw().getProcessor(t).getDefaultCPUProcessor().applyRGB(by_ocio)

    assert by_cli.shape == pixels.shape
    np.testing.assert_allclose(by_ocio, by_cli, rtol=1e-6, atol=1e-7)
    # ... and it is a change: the plate did not come back as it went in.
    assert np.abs(by_cli - pixels).max() > 1e-2


@pytest.mark.parametrize("method", ["rootpoly", "hueplane"])
def test_native_methods_equal_bandlight_apply(tmp_path, method):
    # `bandlight apply --method rootpoly` (or hueplane) applies the C++
    # Relighter's op natively, as bandlight.relight does.
    src = tmp_path / "plate.exr"
    out = tmp_path / f"plate_{method}.exr"
    pixels = plate()
    write_exr(src, pixels)
    run_cli("apply", src, out, "--from", "F2", "--to", "D65", "--method", method)
    by_cli = read_exr(out)
    by_python = bandlight.relight(pixels, "F2", "D65", method)
    np.testing.assert_array_equal(by_python, by_cli)
    assert np.abs(by_python - pixels).max() > 1e-2


def test_relight_agrees_with_the_ocio_transform():
    pixels = plate()
    for method in ("band3-wp", "metamer"):
        t = bandlight.illuminant_change("F11", "A", method)
        by_ocio = pixels.copy()
        OCIO.Config.CreateRaw().getProcessor(t).getDefaultCPUProcessor().applyRGB(by_ocio)
        np.testing.assert_allclose(bandlight.relight(pixels, "F11", "A", method), by_ocio,
                                   rtol=2e-6, atol=1e-7)


def test_upsample_and_rootpoly_are_lattices():
    t = bandlight.illuminant_change("A", "D65", "rootpoly", lut_size=33)
    kinds = [type(p).__name__ for p in t]
    assert "Lut3DTransform" in kinds
    lut = next(p for p in t if isinstance(p, OCIO.Lut3DTransform))
    assert lut.getGridSize() == 33
    # The LUT follows the native map on plate colours (channels 0.3-1 of
    # their level, docs/accuracy.md), at any level.
    rng = np.random.default_rng(5)
    pixels = (rng.uniform(0.3, 1.0, (500, 3)) * 2.0 ** rng.uniform(-6, 6, (500, 1)))
    pixels = pixels.astype(np.float32)
    native = bandlight.relight(pixels, "A", "D65", "rootpoly")
    by_lut = pixels.copy()
    OCIO.Config.CreateRaw().getProcessor(t).getDefaultCPUProcessor().applyRGB(by_lut)
    error = np.abs(by_lut - native).max(axis=1) / native.max(axis=1)
    assert error.max() < 0.03


def test_band_space_and_material_tint():
    to_bands = bandlight.band_space(working_space="lin-rec709")
    assert type(to_bands) is OCIO.GroupTransform
    m = processor_matrix(to_bands)
    np.testing.assert_allclose(m, bandlight.working_to_band_matrix(working_space="rec709"),
                               atol=1e-6)
    # Gold's R_diff (R, G, B) = (0.5, 0.5, 0.0) is (VB, VG, VR) = (0.0, 0.5, 0.5).
    tint = bandlight.material_tint([0.0, 0.5, 0.5], working_space="lin-rec709")
    expected = (bandlight.band_to_working_matrix(working_space="rec709")
                @ np.diag([0.0, 0.5, 0.5])
                @ bandlight.working_to_band_matrix(working_space="rec709"))
    np.testing.assert_allclose(processor_matrix(tint), expected, atol=1e-6)
    # A Spectrum tints by its band means.
    tcs = bandlight.reflectances("TCS09")[0]
    np.testing.assert_allclose(
        processor_matrix(bandlight.material_tint(tcs)),
        processor_matrix(bandlight.material_tint(list(tcs.band_means())))
        , atol=1e-7)
    with pytest.raises(ValueError):
        bandlight.material_tint([0.5, 0.5])  # not one value per band


def test_lights_as_spectra_and_files(tmp_path):
    # A Spectrum and the same spectrum from a file give the same transform.
    d50 = bandlight.illuminant("D50")
    path = tmp_path / "d50.csv"
    path.write_text("nm,mine\n" + "".join(f"{w:g},{v!r}\n" for w, v in
                                          zip(d50.wavelengths, d50.values)))
    by_name = bandlight.illuminant_change_matrix("A", "D50", "band3")
    by_spectrum = bandlight.illuminant_change_matrix("A", d50, "band3")
    by_file = bandlight.illuminant_change_matrix("A", str(path), "band3")
    by_path = bandlight.illuminant_change_matrix("A", path, "band3")
    for m in (by_spectrum, by_file, by_path):
        np.testing.assert_allclose(m, by_name, atol=1e-12)


def test_training_remittances_change_fit3x3():
    default = bandlight.illuminant_change_matrix("A", "F11", "fit3x3")
    own = bandlight.illuminant_change_matrix(
        "A", "F11", "fit3x3", training=bandlight.reflectances("TCS")[8:])
    assert np.abs(default - own).max() > 1e-3
    with pytest.raises(ValueError, match="not fitted"):
        bandlight.illuminant_change_matrix("A", "F11", "bradford", training="TCS")


def test_method_names():
    assert bandlight.method_name("BAND3-WP") == "band3-wp"
    assert bandlight.look_name("Band3", "a", "d65") == "band3_A_to_D65"
    assert "rootpoly" in bandlight.methods()
    assert bandlight.linear_methods() == ["none", "vonkries", "bradford", "cat02", "band3",
                                          "band3-wp"]
    assert "Bradford" in bandlight.describe_method("bradford")


def test_plates_keywords_match_the_command(tmp_path):
    # Each convention's transform is the command's: lut --plates ... writes
    # the same matrix the Python transform holds.
    for plates, adaptation in (("balanced", "cat02"), ("balanced", "bradford"), ("lit", "cat02")):
        t = bandlight.illuminant_change("F11", "D65", "fit3x3", plates=plates,
                                        adaptation=adaptation)
        clf = tmp_path / f"fit3x3_{plates}_{adaptation}.clf"
        run_cli("lut", "--from", "F11", "--to", "D65", "--method", "fit3x3", "--plates", plates,
                "--adaptation", adaptation, "-o", clf)
        from_file = OCIO.Config.CreateRaw().getProcessor(OCIO.FileTransform(src=str(clf)))
        np.testing.assert_allclose(processor_matrix(t), bandlight.measure_matrix(from_file),
                                   rtol=0, atol=1e-6)
    # Bradford-balanced plates through the Bradford look: the identity.
    m = bandlight.illuminant_change_matrix("A", "D65", "bradford", plates="balanced",
                                           adaptation="bradford")
    np.testing.assert_allclose(m, np.eye(3), atol=1e-12)


def test_plates_errors_are_value_errors():
    with pytest.raises(ValueError, match=r"unknown plates 'graded' \(lit, balanced\)"):
        bandlight.illuminant_change("A", "D65", plates="graded")
    with pytest.raises(ValueError, match=r"needs the camera that shot the plates"):
        bandlight.Relighter("A", "D65", "rootpoly-camera")
    with pytest.raises(OSError):
        bandlight.Relighter("A", "D65", "rootpoly-camera", camera="/nonexistent/camera.json")


def test_rootpoly_camera_with_a_camera_file(tmp_path):
    # A camera of three Gaussian channels, in the rawtoaces JSON layout.
    wl = np.arange(380, 781, 5)
    g = lambda peak: np.exp(-0.5 * ((wl - peak) / 32.0) ** 2)
    camera = tmp_path / "gaussian.json"
    camera.write_text(json.dumps({"header": {"manufacturer": "test", "model": "gauss"},
                                  "spectral_data": {"data": {"main": {
                                      str(int(w)): [float(r), float(gg), float(b)]
                                      for w, r, gg, b in zip(wl, g(605), g(535), g(450))}}}}))
    r = bandlight.Relighter("A", "D65", "rootpoly-camera", camera=camera)
    grey = np.full((4, 3), 0.18, dtype=np.float32)
    np.testing.assert_allclose(r.apply(grey), grey, rtol=1e-5)
    doc = bandlight.accuracy(["A", "D65"], ["rootpoly", "rootpoly-camera"], ideal_only=True,
                             exposures=[1.0], plates="balanced", camera=camera, cost=False)
    assert doc["camera"]["file"] == str(camera) and doc["camera"]["idt_light"] == "D55"
    sources = {(row["method"], row["camera"]) for row in doc["rows"]}
    assert ("rootpoly-camera", "camera-daylight-idt") in sources
    assert ("rootpoly", "camera") in sources
