# SPDX-License-Identifier: BSD-3-Clause
"""Scenes rendered to numpy images, against `bandlight render`."""

import numpy as np
import OpenImageIO as oiio
import pytest

import bandlight
from conftest import SCENES, cli_error, run_cli

SMALL = """\
camera: {position: [0, 0, 5], look_at: [0, 0, 0], fov: 30, width: 40, height: 30}
render: {mode: band3, output: acescg}
lights:
  - {type: point, position: [3, 4, 5], spectrum: A}
  - {type: ambient, spectrum: A, intensity: 0.1}
materials:
  gold: lecture
objects:
  - {sphere: {center: [0, 0, 0], radius: 1}, material: gold}
"""


def read_image(path):
    inp = oiio.ImageInput.open(str(path))
    assert inp, oiio.geterror()
    px = inp.read_image("float")
    inp.close()
    return px


@pytest.mark.parametrize("scene, mode", [
    ("materials_A.yaml", None),
    ("tcs_grid_F11.yaml", "spectral"),
    ("narrowband.yaml", "band6"),
    ("counterexample.yaml", None),
])
def test_render_equals_the_command(tmp_path, scene, mode):
    out = tmp_path / "render.exr"
    run_cli("render", SCENES / scene, "-o", out, *(["--mode", mode] if mode else []))
    by_cli = read_image(out)
    image = bandlight.render(SCENES / scene, mode=mode)
    assert image.dtype == np.float32
    assert image.shape == by_cli.shape
    np.testing.assert_array_equal(image, by_cli)
    assert image.max() > 0


def test_counterexample_in_band_values():
    # SPEC 1.4: the band model gives (0, 0.2, 0) in band space where the
    # spectral answer is black.
    image = bandlight.render(SCENES / "counterexample.yaml")
    assert image.shape == (64, 64, 3)
    np.testing.assert_allclose(image[32, 32], [0.0, 0.2, 0.0], atol=1e-6)


def test_render_text_planned_and_unplanned():
    image = bandlight.render(text=SMALL)
    assert image.shape == (30, 40, 3)
    literal = bandlight.render(text=SMALL, unplanned=True)
    np.testing.assert_allclose(image, literal, atol=1e-6)
    spectral = bandlight.render(text=SMALL, mode="spectral", threads=1)
    assert np.abs(spectral - image).max() > 1e-4  # band3 is not the spectral answer
    plan = bandlight.explain_scene(text=SMALL)
    assert "light" in plan


def test_explain_equals_the_command(tmp_path):
    path = tmp_path / "small.yaml"
    path.write_text(SMALL)
    printed = run_cli("render", path, "--explain").stdout
    assert bandlight.explain_scene(path) == printed


def test_scene_errors_name_file_and_line(tmp_path):
    bad = SMALL.replace("radius: 1", "radius: -1")
    with pytest.raises(ValueError, match=r"^<scene>:9: "):
        bandlight.render(text=bad)
    path = tmp_path / "bad.yaml"
    path.write_text(bad)
    with pytest.raises(ValueError) as e:
        bandlight.render(path)
    assert str(e.value) == cli_error("render", path, "-o", tmp_path / "x.exr")
    with pytest.raises(FileNotFoundError) as e:
        bandlight.render(tmp_path / "missing.yaml")
    assert str(e.value) == cli_error("render", tmp_path / "missing.yaml")
    with pytest.raises(ValueError, match="only band mode"):
        bandlight.render(SCENES / "counterexample.yaml", mode="spectral")
    with pytest.raises(ValueError, match="one of the two"):
        bandlight.render()
