# SPDX-License-Identifier: BSD-3-Clause
"""Colorimetry against the command and published values, vectorised."""

import csv

import numpy as np
import pytest

import bandlight
from conftest import ROBUSTNESS_DATA, SPECTRAL_DATA, cli_json


@pytest.mark.parametrize("illuminant", ["A", "D65", "F11", "D75", "3200K"])
@pytest.mark.parametrize("observer", ["1931", "1964"])
def test_xyz_equals_the_command(illuminant, observer):
    by_cli = cli_json("xyz", "--illuminant", illuminant, "--reflectance", "TCS",
                      "--observer", observer, "--json")
    white = bandlight.xyz(illuminant, observer=observer)
    np.testing.assert_allclose(white, by_cli["white_XYZ"], rtol=1e-13)
    rows = bandlight.xyz(illuminant, "TCS", observer=observer)
    assert rows.shape == (15, 3)
    np.testing.assert_allclose(rows, [s["XYZ"] for s in by_cli["samples"]], rtol=1e-12)
    lab = bandlight.xyz_to_lab(rows, white)
    np.testing.assert_allclose(lab, [s["Lab"] for s in by_cli["samples"]], rtol=1e-10,
                               atol=1e-10)
    xy = bandlight.xyz_to_xyy(rows)[:, :2]
    np.testing.assert_allclose(xy, [s["xy"] for s in by_cli["samples"]], rtol=1e-12)


def test_xyz_of_one_surface_and_of_a_file():
    tcs = bandlight.reflectances("TCS")
    one = bandlight.xyz("A", tcs[2])
    assert one.shape == (3,)
    np.testing.assert_allclose(one, bandlight.xyz("A", tcs)[2], rtol=1e-14)
    # A remittance file that stops short of the visible range: the command's
    # numbers, and its note as a warning.
    path = ROBUSTNESS_DATA / "grey_400_700.csv"
    by_cli = cli_json("xyz", "--illuminant", "D65", "--reflectance", path, "--json")
    with pytest.warns(bandlight.NoteWarning):
        rows = bandlight.xyz("D65", str(path))
    np.testing.assert_allclose(rows, [s["XYZ"] for s in by_cli["samples"]], rtol=1e-12)


def test_xyz_integrator_is_vectorised():
    integ = bandlight.XyzIntegrator("F11")
    tcs = bandlight.reflectances("TCS")
    samples = np.stack([s.resampled(integ.wavelengths[0], 5.0, len(integ.wavelengths)).values
                        for s in tcs[:14]])
    # Any leading shape; XYZ = samples @ weights.
    batch = integ(samples.reshape(2, 7, -1))
    assert batch.shape == (2, 7, 3)
    np.testing.assert_allclose(batch.reshape(14, 3), samples @ integ.weights, rtol=1e-12)
    # Spectra are resampled (edge-extended) as SurfaceXyz does.
    np.testing.assert_allclose(integ(tcs), bandlight.xyz("F11", tcs), rtol=1e-10)
    np.testing.assert_allclose(integ.white, bandlight.xyz("F11"), rtol=1e-14)
    # A perfect white reflector on the grid has Y = 100.
    assert integ(np.ones(len(integ.wavelengths)))[1] == pytest.approx(100.0)
    with pytest.raises(ValueError, match="integrator's grid"):
        integ(np.ones(7))


def sharma_pairs():
    with open(SPECTRAL_DATA / "ciede2000_sharma2005.csv") as f:
        rows = [r for r in csv.reader(line for line in f if not line.startswith("#")) if r]
    header, data = rows[0], np.array(rows[1:], dtype=float)
    return header, data


def test_ciede2000_sharma_table_vectorised():
    header, data = sharma_pairs()
    assert len(data) == 34
    lab1, lab2, expected = data[:, 1:4], data[:, 4:7], data[:, 7]
    de = bandlight.delta_e2000(lab1, lab2)
    assert de.shape == (34,)
    np.testing.assert_allclose(de, expected, atol=5e-5)
    # Symmetric, zero on equal colours, a float for one pair, broadcasting.
    np.testing.assert_allclose(bandlight.delta_e2000(lab2, lab1), de, atol=1e-12)
    assert isinstance(bandlight.delta_e2000(lab1[0], lab2[0]), float)
    assert bandlight.delta_e2000(lab1[0], lab2[0]) == pytest.approx(expected[0], abs=5e-5)
    grid = bandlight.delta_e2000(lab1[:, None, :], lab2[None, :5, :])
    assert grid.shape == (34, 5)
    np.testing.assert_allclose(grid[:, 0], [bandlight.delta_e2000(a, lab2[0]) for a in lab1])
    np.testing.assert_allclose(bandlight.delta_e76(lab1, lab2),
                               np.linalg.norm(lab1 - lab2, axis=1), rtol=1e-12)
    with pytest.raises(ValueError, match="broadcast"):
        bandlight.delta_e2000(np.zeros((4, 3)), np.zeros((5, 3)))
    with pytest.raises(ValueError, match="3 values in its last dimension"):
        bandlight.delta_e2000(np.zeros((4, 2)), np.zeros((4, 2)))


def test_lab_round_trip_over_an_image():
    rng = np.random.default_rng(3)
    xyz = rng.uniform(0, 100, (64, 48, 3))
    white = bandlight.xyz("D50")
    lab = bandlight.xyz_to_lab(xyz, white)
    assert lab.shape == (64, 48, 3)
    np.testing.assert_allclose(bandlight.lab_to_xyz(lab, white), xyz, rtol=1e-10, atol=1e-10)
    np.testing.assert_allclose(bandlight.xyz_to_lab(white, white), [100, 0, 0], atol=1e-12)
    np.testing.assert_allclose(bandlight.xyy_to_xyz(bandlight.xyz_to_xyy(xyz)), xyz,
                               rtol=1e-11)


@pytest.mark.parametrize("illuminant", ["F1", "F11", "A", "D65"])
def test_cri_equals_the_command(illuminant):
    by_cli = cli_json("cri", "--illuminant", illuminant, "--json")
    cri = bandlight.cri(illuminant)
    assert list(cri) == list(by_cli)
    for key in ("cct_K", "duv", "Ra"):
        assert cri[key] == pytest.approx(by_cli[key], rel=1e-12, abs=1e-12)
    np.testing.assert_allclose(cri["R"], by_cli["R"], rtol=1e-12)
    assert cri["outside_duv_tolerance"] == by_cli["outside_duv_tolerance"]


def test_cri_published_values():
    # CIE 15:2004 Table T.8.2: F11 has Ra 83, CCT 4000 K.
    cri = bandlight.cri("F11")
    assert round(cri["Ra"]) == 83
    assert cri["cct_K"] == pytest.approx(4000, abs=15)
    cct, duv = bandlight.cct(bandlight.xyz("F11"))
    assert (cct, duv) == (pytest.approx(cri["cct_K"]), pytest.approx(cri["duv"]))
    ccts, _ = bandlight.cct(np.stack([bandlight.xyz(n) for n in ("A", "D65")]))
    np.testing.assert_allclose(ccts, [2856, 6504], atol=3)


def test_chromatic_adaptation_and_rgb_spaces():
    src, dst = bandlight.xyz("A"), bandlight.xyz("D65")
    for method in ("vonkries", "bradford", "cat02", "sharp"):
        m = bandlight.adaptation_matrix(src, dst, method)
        np.testing.assert_allclose(m @ src, dst, rtol=1e-12)
    with pytest.raises(ValueError):
        bandlight.adaptation_matrix(src, dst, "vonkries2")
    spaces = {s["name"]: s for s in bandlight.rgb_spaces()}
    assert set(spaces) >= {"acescg", "rec709", "rec2020", "p3-d65", "aces2065-1", "ebu3213"}
    assert spaces["rec709"]["primaries"][0] == pytest.approx((0.64, 0.33))
    with pytest.raises(ValueError, match="rec709.*colorspace=srgb"):
        bandlight.rgb_to_xyz_matrix("srgb")  # the encoding, not a linear space
    m = bandlight.rgb_to_xyz_matrix("lin-srgb")
    np.testing.assert_allclose(m[1], [0.2126, 0.7152, 0.0722], atol=1e-4)
    # ACEScg: S-2014-004's matrix.
    np.testing.assert_allclose(bandlight.rgb_to_xyz_matrix("ap1")[0],
                               [0.6624541811, 0.1340042065, 0.1561876870], atol=1e-9)


def test_quality_equals_the_command_and_pickles():
    import pickle
    lights = ["F2", "F11", "planck:3200"]
    by_cli = cli_json("quality", *lights, "--reference", "D65", "--json")
    scored = bandlight.quality(lights, reference="D65")
    assert [q.light for q in scored] == [d["light"] for d in by_cli]
    for q, d in zip(scored, by_cli):
        assert q.cct == pytest.approx(d["cct"], rel=1e-12)
        assert q.duv == pytest.approx(d["duv"], rel=1e-12, abs=1e-15)
        assert q.cri == d["cri"]
        assert list(q.warnings) == d["warnings"]
        assert pickle.loads(pickle.dumps(q)) == q
    # One light gives one record; a Spectrum is a light too.
    one = bandlight.quality(bandlight.illuminant("F11"))
    assert round(one.cri["Ra"]) == 83  # CIE 15:2004 Table T.8.2
    assert len(one.cri["R"]) == 15


def test_quality_refuses_what_it_cannot_score():
    with pytest.raises(ValueError, match="unknown illuminant 'nolight'"):
        bandlight.quality("nolight")
    with pytest.raises(TypeError):
        bandlight.quality("F2", refrence="A")


def test_quality_docs_example_runs():
    # docs/quality.md's Python example, as printed.
    import re
    from conftest import SOURCE_DIR
    text = (SOURCE_DIR / "docs" / "quality.md").read_text()
    blocks = re.findall(r"```python\n(.*?)```", text, re.S)
    assert len(blocks) == 1
    exec(compile(blocks[0], "docs/quality.md", "exec"), {})
