# SPDX-License-Identifier: BSD-3-Clause
"""bandlight.idt: the document `bandlight idt --json` writes, with numpy
matrices and the written config as a PyOpenColorIO.Config."""

import json

import numpy as np
import pytest

import bandlight
from conftest import SOURCE_DIR, cli_json

D21 = SOURCE_DIR / "tests/data/rawtoaces/arri_d21_380_780_5.json"


def test_idt_matches_the_command(tmp_path):
    doc = bandlight.idt(D21, "A,3200K,D55", config=tmp_path / "cfg")
    assert [i["light"] for i in doc["idts"]] == ["A", "3200K", "D55"]
    for i in doc["idts"]:
        m = i["matrix"]
        assert isinstance(m, np.ndarray) and m.shape == (3, 3)
        # White kept; gains normalised to green.
        np.testing.assert_allclose(m @ np.ones(3), np.ones(3), atol=1e-12)
        assert i["gains"][1] == 1.0
        np.testing.assert_allclose(i["raw_to_working"], m @ np.diag(i["gains"]), rtol=1e-12)
        assert i["objective_rms_de76"]["optimum"] <= i["objective_rms_de76"]["first_order"]
    config = doc["config"]
    space = config.getColorSpace("Input - arri d21 - D55")
    assert space.getFamily() == "Input"
    # Each light's colour space, as an object of that config.
    assert list(doc["colorspaces"]) == ["A", "3200K", "D55"]
    assert doc["colorspaces"]["D55"].getName() == "Input - arri d21 - D55"
    assert doc["colorspaces"]["A"].getEncoding() == "scene-linear"
    processor = config.getProcessor("Input - arri d21 - D55", "ACES2065-1").getDefaultCPUProcessor()
    expected = doc["idts"][2]["raw_to_working"]
    for column in range(3):
        pixel = [0.0, 0.0, 0.0]
        pixel[column] = 1.0
        np.testing.assert_allclose(processor.applyRGB(pixel), expected[:, column], atol=1e-6)
    command = cli_json("idt", "--camera", D21, "--lights", "A,3200K,D55", "--json", "-")
    for mine, theirs in zip(doc["idts"], command["idts"]):
        np.testing.assert_array_equal(mine["matrix"], np.array(theirs["matrix"]))


def test_idt_refuses_a_zero_neutral():
    with pytest.raises(ValueError, match="as_shot_neutral"):
        bandlight.idt(D21, as_shot_neutral=(0.5, 0.0, 0.8))
    with pytest.raises(ValueError, match="interpolate"):
        bandlight.idt(D21, interpolate=["3200K"])


def test_interpolated_idt_stays_near_the_fitted_one():
    # The D21's 3200 K and 5600 K calibrations; the curve as the command's.
    doc = bandlight.idt(D21, interpolate="3200K,5600K")
    section = doc["interpolation"]
    assert section["set"] == "TCS" and section["interpolated"] == "color_matrix"
    lights = [c["light"] for c in section["calibrations"]]
    assert lights == ["3200K", "5600K"]
    for c in section["calibrations"]:
        assert isinstance(c["color_matrix"], np.ndarray) and c["color_matrix"].shape == (3, 3)
    curve = section["curve"]
    assert [p["cct"] for p in curve] == list(range(2800, 6501, 100))
    assert all(p["mean_vs_direct"] <= 0.3 for p in curve)
    command = cli_json("idt", "--camera", D21, "--interpolate", "3200K,5600K", "--json", "-")
    assert curve == command["interpolation"]["curve"]


def _rows(path):
    return [l.split(",") for l in path.read_text().splitlines()
            if l.strip() and not l.startswith("#") and l[0].isdigit()]


def test_chart_idt_from_simulated_rgb_equals_the_sensitivity_idt(tmp_path):
    # The 190 as a chart, its camera RGB simulated from the D21's
    # sensitivities under D55 (both 380-780 nm at 5 nm).
    chart = SOURCE_DIR / "data/ref/rawtoaces_190.csv"
    reflect = np.array([[float(v) for v in r[1:]] for r in _rows(chart)])
    light = np.array([float(r[1]) for r in _rows(SOURCE_DIR / "data/illuminant/D55.csv")])
    camera = json.loads(D21.read_text())["spectral_data"]["data"]["main"]
    sens = np.array([camera[str(nm)] for nm in range(380, 785, 5)])
    assert reflect.shape == (81, 190) and light.shape == (81,)
    raw = (reflect * light[:, None]).T @ sens
    csv = tmp_path / "chart.csv"
    csv.write_text("name,R,G,B\n" + "".join(f"p{i},{r:.17g},{g:.17g},{b:.17g}\n"
                                           for i, (r, g, b) in enumerate(raw)))
    with pytest.warns(bandlight.NoteWarning, match="patch18"):  # a -1.7e-18 in the file
        from_chart = bandlight.idt(chart_rgb=csv, chart=chart, light="D55", rootpoly=2)
    from_camera = bandlight.idt(D21, "D55")
    assert from_chart["chart"]["patches"] == 190
    # The root polynomial has more freedom: on its own chart it fits better.
    poly = from_chart["chart"]["rootpoly"]
    assert poly["degree"] == 2 and len(poly["matrix"][0]) == 6
    chart_error = from_chart["idts"][0]["error"][str(chart)]["mean"]
    assert 0.0 < poly["error"][str(chart)]["mean"] < chart_error
    np.testing.assert_allclose(from_chart["idts"][0]["matrix"], from_camera["idts"][0]["matrix"],
                               atol=1e-6)
    np.testing.assert_allclose(from_chart["idts"][0]["gains"], from_camera["idts"][0]["gains"],
                               atol=1e-9)


def test_camera_looks_name_the_input_space_they_expect(tmp_path):
    # rootpoly-camera looks take plates through the camera's one fixed IDT:
    # their description names the colour space `idt` writes for that light.
    doc = bandlight.idt(D21, "D55", config=tmp_path / "camera")
    space = doc["idts"][0]["colorspace"]
    looks = bandlight.config(tmp_path / "looks", illuminants="A,D65",
                             methods=["rootpoly-camera"], camera=D21,
                             camera_idt="D55")
    described = [looks.getLook(n).getDescription() for n in looks.getLookNames()]
    assert described and all(f"input colour space '{space}'" in d for d in described)
    assert doc["config"].getColorSpace(space) is not None


def test_wall_equals_the_command(tmp_path):
    # The docs' RGB wall (docs/wall.md), through Python and the command.
    from conftest import SOURCE_DIR
    wall = SOURCE_DIR / "docs" / "examples" / "wall"
    camera = SOURCE_DIR / "tests" / "data" / "rawtoaces" / "arri_d21_380_780_5.json"
    emitters = {"R": wall / "red.csv", "G": wall / "green.csv", "B": wall / "blue.csv"}
    doc = bandlight.wall(emitters, camera, ["5600K", "3200K"], content_space="rec709",
                         out=tmp_path / "py")
    by_cli = cli_json("wall", "--emitter", *[f"{k}={v}" for k, v in emitters.items()],
                      "--camera", camera, "--white-balance", "5600K", "3200K",
                      "--content-space", "rec709", "--out", tmp_path / "cli", "--json")
    assert [b["key"] for b in doc["white_balances"]] == ["5600K", "3200K"]
    for a, b in zip(doc["white_balances"], by_cli["white_balances"]):
        np.testing.assert_allclose(a["in_frustum"]["drive_matrix"],
                                   b["in_frustum"]["drive_matrix"], rtol=1e-12)
        assert a["white_scores"]["cri"]["Ra"] == pytest.approx(b["white_scores"]["cri"]["Ra"])
    assert (tmp_path / "py" / "config.ocio").exists()
    with pytest.raises(ValueError, match="at least three emitters|3 emitters"):
        bandlight.wall({"R": wall / "red.csv"}, camera, "5600K", content_space="rec709",
                       out=tmp_path / "bad")
