# SPDX-License-Identifier: BSD-3-Clause
"""The band model: band sets, band means and band matrices."""

import numpy as np
import pytest

import bandlight
from conftest import cli_json


@pytest.mark.parametrize("args, kwargs", [
    ([], {}),
    (["--bands", "400,450,500,550,600,650,700"], {"bands": "400,450,500,550,600,650,700"}),
    (["--observer", "1964", "--rule", "exact"], {"observer": "1964", "rule": "exact"}),
])
def test_tables_equal_the_command(args, kwargs):
    by_cli = cli_json("tables", *args, "--json")
    tables = bandlight.tables(**kwargs)
    assert list(tables) == list(by_cli)
    assert tables["bands"] == by_cli["bands"]
    assert (tables["observer"], tables["rule"]) == (by_cli["observer"], by_cli["rule"])
    for group in ("matching_functions",):
        for key, rows in by_cli[group].items():
            for k, row in rows.items():
                np.testing.assert_allclose(tables[group][key][k], row, rtol=1e-12, atol=1e-15)
    for key, value in by_cli["condition_number"].items():
        assert tables["condition_number"][key] == pytest.approx(value, rel=1e-12)
    for group in ("illuminants", "remittances"):
        assert list(tables[group]) == list(by_cli[group])
        for name, row in by_cli[group].items():
            np.testing.assert_allclose(tables[group][name], row, rtol=1e-12, atol=1e-15)


def test_the_lectures_acceptance_tables():
    # SPEC 1.2: CIE 1931 band rows (to 1e-4), illuminant band means (to 1e-3;
    # A's I_B to 5e-3).
    m = bandlight.matching_band_matrix()
    np.testing.assert_allclose(m, [[0.1666, 0.4250, 0.4084],
                                   [0.0607, 0.7506, 0.1888],
                                   [0.9518, 0.0481, 0.0001]], atol=1e-4)
    np.testing.assert_allclose(m.sum(axis=1), 1.0, atol=1e-14)
    expected = {"D65": (1.0, 0.9747, 0.7880), "A": (0.2050, 0.5631, 1.0),
                "C": (1.0, 0.9130, 0.7829), "F2": (0.6008, 1.0, 0.4746),
                "F11": (0.7060, 1.0, 0.8008)}
    for name, bands in expected.items():
        np.testing.assert_allclose(bandlight.illuminant_bands(name), bands,
                                   atol=5e-3 if name == "A" else 1e-3)


def test_band_sets():
    lecture = bandlight.BandSet.lecture()
    assert lecture.names == ["VB", "VG", "VR"]
    assert lecture.bands == [("VB", 400, 500), ("VG", 500, 600), ("VR", 600, 700)]
    assert len(bandlight.BandSet.equal(6)) == 6
    assert bandlight.BandSet([380, 480, 560, 780]).describe() == "380,480,560,780"
    disjoint = bandlight.BandSet.named([("blue", 420, 460), ("red", 620, 660)])
    assert disjoint.describe() == "420,460,620,660"
    # Anywhere bands are taken, a str or a list of edges will do.
    np.testing.assert_array_equal(bandlight.illuminant_bands("A", "400,500,600,700"),
                                  bandlight.illuminant_bands("A", lecture))
    np.testing.assert_array_equal(bandlight.illuminant_bands("A", [400, 500, 600, 700]),
                                  bandlight.illuminant_bands("A"))
    with pytest.raises(ValueError, match="'x' is not a wavelength"):
        bandlight.BandSet("400,x,700")
    with pytest.raises(ValueError):
        bandlight.BandSet([500, 400])


def test_band_means_of_spectra():
    tcs = bandlight.reflectances("TCS")
    rows = bandlight.remittance_bands("TCS")
    assert rows.shape == (15, 3)
    np.testing.assert_allclose(rows[3], bandlight.remittance_bands(tcs[3]))
    np.testing.assert_allclose(rows[3], tcs[3].band_means())
    # The band model's rule: the average of the 5 nm samples with a <= lambda < b.
    v = tcs[3].values
    w = tcs[3].wavelengths
    np.testing.assert_allclose(rows[3], [v[(w >= a) & (w < a + 100)].mean()
                                         for a in (400, 500, 600)], rtol=1e-12)
    exact = tcs[3].band_means(rule="exact")
    np.testing.assert_allclose(exact, [tcs[3].integrate(a, a + 100) / 100
                                       for a in (400, 500, 600)], rtol=1e-12)
    d65 = bandlight.illuminant("D65")
    raw = d65.band_means()
    np.testing.assert_allclose(bandlight.illuminant_bands(d65), raw / raw.max(), rtol=1e-12)


def test_band_matrices():
    to_xyz, from_xyz, condition = bandlight.band_to_colour_matrix()
    np.testing.assert_allclose(to_xyz @ from_xyz, np.eye(3), atol=1e-12)
    assert condition == pytest.approx(4.35, abs=0.01)  # docs/science.md: the lecture's bands
    assert bandlight.condition_number(to_xyz) == pytest.approx(condition)
    to_bands = bandlight.working_to_band_matrix(working_space="acescg")
    back = bandlight.band_to_working_matrix(working_space="acescg")
    np.testing.assert_allclose(back @ to_bands, np.eye(3), atol=1e-12)
    six = bandlight.working_to_band_matrix("400,450,500,550,600,650,700")
    assert six.shape == (6, 3)
    with pytest.raises(ValueError):
        bandlight.band_to_colour_matrix("400,450,500,550,600,650,700")  # not three bands
    assert bandlight.MAX_BAND_CONDITION == 1000.0
