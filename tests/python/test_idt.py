# SPDX-License-Identifier: BSD-3-Clause
"""bandlight.idt: the document `bandlight idt --json` writes, with numpy
matrices and the written config as a PyOpenColorIO.Config."""

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
