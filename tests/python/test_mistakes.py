# SPDX-License-Identifier: BSD-3-Clause
"""What Python users get wrong, as the command's users do: each is refused
with the library's message, before any work, and nothing is lost."""

import os

import pytest

import bandlight
from test_apply import write_plate


def test_a_look_with_the_keywords_of_a_change_of_light_is_refused(tmp_path):
    write_plate(tmp_path / "plate.exr")
    config = tmp_path / "config"
    bandlight.config(config, illuminants="A,D65", methods=["bradford"])
    with pytest.raises(ValueError, match=r"look applies a look .*src, dst, method.*camera"):
        bandlight.apply(tmp_path / "plate.exr", tmp_path / "out.exr",
                        look="bradford_A_to_D65", config=config, src="F11", dst="A",
                        method="band3", camera=tmp_path / "missing.csv")
    assert not (tmp_path / "out.exr").exists()


@pytest.mark.parametrize("keyword, value", [("method", "bradford"), ("working_space", "acescg"),
                                            ("adaptation", "cat02"), ("camera_idt", "D55")])
def test_a_look_with_a_keyword_given_at_its_default_value_is_refused(tmp_path, keyword, value):
    # Given is given: the default's own value beside a look is as ignored as
    # any other, so it is refused in the command's words (--method there).
    write_plate(tmp_path / "plate.exr")
    config = tmp_path / "config"
    bandlight.config(config, illuminants="A,D65", methods=["bradford"])
    with pytest.raises(ValueError) as e:
        bandlight.apply(tmp_path / "plate.exr", tmp_path / "out.exr",
                        look="bradford_A_to_D65", config=config, **{keyword: value})
    assert str(e.value) == (f"look applies a look of config as it is: {keyword} do not apply "
                            "to it (give the look, or the change of light)")
    assert not (tmp_path / "out.exr").exists()
    # Not given: the look applies.
    bandlight.apply(tmp_path / "plate.exr", tmp_path / "out.exr", look="bradford_A_to_D65",
                    config=config)
    assert (tmp_path / "out.exr").exists()


def test_an_empty_output_folder_is_refused(tmp_path):
    os.chdir(tmp_path)
    with pytest.raises(ValueError, match=r"an empty path"):
        bandlight.config("", illuminants="A,D65", methods=["bradford"])
    assert not any(tmp_path.iterdir())
    # Not given at all: the config is returned, nothing written.
    assert len(list(bandlight.config(illuminants="A,D65", methods=["bradford"]).getLooks())) == 2


def test_a_spectral_image_is_not_written_over_itself(tmp_path):
    scene = tmp_path / "scene.yaml"
    scene.write_text("camera: {position: [0, 0, 5], look_at: [0, 0, 0], fov: 40, width: 8, "
                     "height: 6}\nrender: {mode: spectral, output: acescg, step: 10}\n"
                     "lights:\n  - {type: directional, direction: [0, 0, -1], spectrum: F11}\n"
                     "materials:\n  red: {diffuse: TCS01}\n"
                     "objects:\n  - {sphere: {center: [0, 0, 0], radius: 1}, material: red}\n")
    from conftest import run_cli
    run_cli("render", scene, "--spectra", "-o", tmp_path / "shot.exr")
    before = (tmp_path / "shot.exr").read_bytes()
    with pytest.raises(ValueError, match="is the input"):
        bandlight.spectral(tmp_path / "shot.exr", tmp_path / "shot.exr", src="F11", dst="D65")
    assert (tmp_path / "shot.exr").read_bytes() == before


def test_the_lut_format_follows_the_extension(tmp_path):
    bandlight.lut(tmp_path / "x.cube", "A", "D65", size=5)
    assert "LUT_3D_SIZE 5" in (tmp_path / "x.cube").read_text()
    with pytest.raises(ValueError, match=r"is named \.clf"):
        bandlight.lut(tmp_path / "y.cube", "A", "D65", format="clf")
    assert not (tmp_path / "y.cube").exists()


def test_srgb_is_an_encoding_not_a_working_space():
    with pytest.raises(ValueError, match=r"rec709.*colorspace=srgb"):
        bandlight.Relighter("A", "D65", working_space="srgb")
    assert bandlight.Relighter("A", "D65", working_space="lin-srgb").working_space == "rec709"


def test_spectra_that_integrate_beyond_float_are_refused_naming_the_pixel(tmp_path):
    import numpy as np
    import OpenImageIO as oiio
    from conftest import cli_error
    grid = np.arange(380.0, 781.0, 10.0)
    spectra = np.full((2, 3, grid.size), 3.4e38, dtype=np.float32)
    # Every value finite, their integral not: never Inf with exit 0.
    with pytest.raises(ValueError, match=r"spectra: pixel 0: .*beyond float's range"):
        bandlight.spectral_to_rgb(spectra, grid, plates="lit")
    spec = oiio.ImageSpec(3, 2, grid.size, "float")
    spec.channelnames = tuple(f"S0.{nm:g}nm" for nm in grid)
    out = oiio.ImageOutput.create(str(tmp_path / "hot.exr"))
    assert out.open(str(tmp_path / "hot.exr"), spec)
    assert out.write_image(spectra)
    out.close()
    assert "pixel (0, 0): its spectrum integrates beyond float's range" in cli_error(
        "spectral", tmp_path / "hot.exr", tmp_path / "rgb.exr", "--plates", "lit")
    assert not (tmp_path / "rgb.exr").exists()


def test_wrong_types_are_type_errors_with_the_library_message(tmp_path):
    # A light's name where colours belong: not pybind11's "nullptr" message.
    with pytest.raises(TypeError, match=r"xyz must be colours.*not a string \('D65'\)"):
        bandlight.cct("D65")
    # Channel names map to wavelengths: a number as a key is named.
    with pytest.raises(TypeError, match=r"channels= maps channel names \(str\).*key 1 \(int\)"):
        bandlight.read_spectral_image(tmp_path / "any.exr", channels={1: 450.0})
    with pytest.raises(TypeError, match=r"wavelength of 'band_00' must be a number"):
        bandlight.read_spectral_image(tmp_path / "any.exr", channels={"band_00": "blue"})
    # A Dask client that is not one: not an AttributeError from inside.
    with pytest.raises(TypeError, match=r"client= must be a distributed.Client.*int"):
        bandlight.apply(tmp_path / "in.####.exr", tmp_path / "out.####.exr", frames="1-2",
                        client=42, src="A", dst="D65")
    with pytest.raises(TypeError, match="one of the two"):
        bandlight.render()


def test_relighters_say_their_plates_and_spectra_do_arithmetic():
    lit = bandlight.Relighter("A", "D65", plates="lit")
    balanced = bandlight.Relighter("A", "D65")
    assert (lit.plates, balanced.plates) == ("lit", "balanced-cat02")
    assert repr(lit) != repr(balanced) and "lit plates" in repr(lit)
    a, d = bandlight.illuminant("A"), bandlight.illuminant("D65")
    for nm in (400.0, 555.0, 700.0):
        assert (d / a)(nm) == pytest.approx(d(nm) / a(nm), rel=1e-12)
        assert (a + 0.5)(nm) == pytest.approx(a(nm) + 0.5, rel=1e-12)
        assert (0.5 + a)(nm) == pytest.approx(a(nm) + 0.5, rel=1e-12)
        assert (a - 0.5)(nm) == pytest.approx(a(nm) - 0.5, rel=1e-12)
    with pytest.raises(ValueError, match="is 0 at"):
        a / (a * 0.0)
