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
    with pytest.raises(TypeError, match="one of the two"):
        bandlight.render()
    with pytest.raises(ValueError, match="not both"):
        bandlight.render(SCENES / "counterexample.yaml", text="lights: []")


def image_bytes(path):
    """A written image's bytes without the time stamp OpenImageIO puts into
    EXRs (capDate), as tests/docs/run_examples.py compares them."""
    import re
    return re.sub(rb"(capDate\0string\0\x13\0\0\0)[^\0]{19}", lambda m: m.group(1) + b"0" * 19,
                  path.read_bytes())


@pytest.mark.parametrize("mode, spectra, compare", [("spectral", True, False),
                                                    ("band3", False, True)])
def test_render_out_writes_the_commands_files(tmp_path, mode, spectra, compare):
    scene = tmp_path / "small.yaml"
    scene.write_text(SMALL)
    (tmp_path / "cli").mkdir()
    (tmp_path / "py").mkdir()
    flags = (["--mode", mode] + (["--compare"] if compare else []) +
             (["--spectra"] if spectra else []))
    printed = run_cli("render", scene, "-o", tmp_path / "cli" / "small.exr", *flags).stdout
    result = bandlight.render(scene, mode=mode, out=tmp_path / "py" / "small.exr",
                              compare=compare, spectra=spectra)
    names = ["small.exr", "small.png"] + (["small_dE00.exr", "small_dE00.png"] if compare else [])
    assert result["files"] == [str(tmp_path / "py" / n) for n in names]
    assert sorted(p.name for p in (tmp_path / "py").iterdir()) == sorted(names)
    for name in names:
        assert image_bytes(tmp_path / "py" / name) == image_bytes(tmp_path / "cli" / name), name
    assert (result["width"], result["height"], result["channels"]) == (40, 30, 3)
    assert result["image"].shape == (30, 40, 3)
    if not spectra:
        np.testing.assert_array_equal(result["image"], read_image(tmp_path / "py" / "small.exr"))
    if compare:
        c = result["comparison"]
        assert c["exr"] == str(tmp_path / "py" / "small_dE00.exr")
        assert f"compare with spectral: {c['pixels']} pixels, ΔE00 mean {c['mean']:.3f}, " \
               f"p95 {c['p95']:.3f}, max {c['max']:.3f}" in printed
        assert c["max"] > 0.0
    assert printed.startswith(result["explanation"])
    assert f"rendered {result['counters']['pixels']} pixels " in printed


def test_compare_on_a_spectral_render_is_refused(tmp_path):
    scene = tmp_path / "small.yaml"
    scene.write_text(SMALL)
    assert "spectral already" in cli_error("render", scene, "--mode", "spectral", "--compare",
                                           "-o", tmp_path / "x.exr")
    with pytest.raises(ValueError, match="spectral already"):
        bandlight.render(scene, mode="spectral", out=tmp_path / "y.exr", compare=True)
    assert not any(tmp_path.glob("*.exr"))


def test_render_preview_where_asked(tmp_path):
    result = bandlight.render(text=SMALL, out=tmp_path / "a.exr", preview=False)
    assert result["files"] == [str(tmp_path / "a.exr")]
    assert sorted(p.name for p in tmp_path.iterdir()) == ["a.exr"]
    (tmp_path / "previews").mkdir()
    result = bandlight.render(text=SMALL, out=tmp_path / "b.exr",
                              preview=tmp_path / "previews" / "b.png")
    assert result["files"] == [str(tmp_path / "b.exr"), str(tmp_path / "previews" / "b.png")]
    assert result["comparison"] is None


def test_render_refuses_outputs_that_do_not_go_together(tmp_path):
    with pytest.raises(ValueError, match=r"^spectra needs spectral mode \(mode=spectral\)"):
        bandlight.render(text=SMALL, out=tmp_path / "a.exr", spectra=True)
    with pytest.raises(ValueError, match=r"^compare writes its ΔE00 map beside the render: give out$"):
        bandlight.render(text=SMALL, compare=True)
    with pytest.raises(ValueError, match=r"^spectra needs spectral mode"):
        bandlight.render(text=SMALL, out=tmp_path / "missing" / "a.exr", spectra=True)
    with pytest.raises(FileNotFoundError):
        bandlight.render(text=SMALL, out=tmp_path / "missing" / "a.exr")
    assert list(tmp_path.iterdir()) == []
