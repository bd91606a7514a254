# SPDX-License-Identifier: BSD-3-Clause
"""Spectra as numpy: the Spectrum class, built-in data, file readers."""

import pathlib
import pickle

import numpy as np
import pytest

import bandlight
from conftest import ROBUSTNESS_DATA, cli_json


def test_spectrum_holds_numpy_arrays():
    s = bandlight.Spectrum(np.arange(380.0, 785.0, 5.0), np.linspace(0, 1, 81), "ramp")
    assert (s.name, s.start, s.step, s.end, len(s)) == ("ramp", 380.0, 5.0, 780.0, 81)
    assert s.wavelengths.dtype == np.float64 and s.values.dtype == np.float64
    np.testing.assert_array_equal(s.wavelengths, np.arange(380.0, 785.0, 5.0))
    np.testing.assert_array_equal(s.values, np.linspace(0, 1, 81))
    with pytest.raises(ValueError):
        s.values[0] = 2.0  # a read-only view of the spectrum's own samples
    # Linear interpolation, zero outside.
    assert s(382.5) == pytest.approx(0.5 * (s.values[0] + s.values[1]))
    np.testing.assert_allclose(s(np.array([[380.0, 780.0], [300.0, 900.0]])),
                               [[0.0, 1.0], [0.0, 0.0]])
    assert s.sum() == pytest.approx(s.values.sum() * 5.0)
    assert s.integrate(380.0, 780.0) == pytest.approx(200.0)  # a ramp 0..1 over 400 nm
    r = s.resampled(400.0, 10.0, 31)
    np.testing.assert_allclose(r.values, (np.arange(400.0, 710.0, 10.0) - 380.0) / 400.0)
    e = r.extended(380.0, 720.0)
    assert (e.start, e.end, e.values[0], e.values[-1]) == (380.0, 720.0, r.values[0],
                                                            r.values[-1])
    assert "ramp" in repr(s) and "81 samples" in repr(s)


def test_spectrum_arithmetic_and_pickle():
    d65 = bandlight.illuminant("D65")
    tcs = bandlight.reflectances("TCS05")[0]
    product = d65 * tcs
    assert product.start == d65.start and product.step == d65.step
    np.testing.assert_allclose(product.values, d65.values * tcs(d65.wavelengths))
    np.testing.assert_allclose((2.0 * d65).values, 2 * d65.values)
    np.testing.assert_allclose((d65 / 4).values, d65.values / 4)
    np.testing.assert_allclose((d65 - d65).values, 0.0)
    again = pickle.loads(pickle.dumps(d65))
    assert again.name == "D65"
    np.testing.assert_array_equal(again.values, d65.values)


def test_bad_spectra_are_refused():
    with pytest.raises(ValueError, match="evenly spaced"):
        bandlight.Spectrum([400, 410, 430], [1, 1, 1], "uneven")
    with pytest.raises(ValueError, match="3 wavelengths but 2 values"):
        bandlight.Spectrum([400, 410, 420], [1, 1])
    with pytest.raises(ValueError, match="not a finite number"):
        bandlight.Spectrum([400, 410, 420], [1, np.nan, 1], "bad")
    with pytest.raises(ValueError, match="increase"):
        bandlight.Spectrum([420, 410, 400], [1, 1, 1])


def test_builtin_illuminants():
    names = bandlight.illuminant_names()
    assert names[:7] == ["A", "C", "D50", "D55", "D65", "D75", "E"]
    assert names[7:] == [f"F{i}" for i in range(1, 13)]
    d65 = bandlight.illuminant("d65")
    assert d65.name == "D65" and (d65.start, d65.step, d65.end) == (300.0, 5.0, 830.0)
    assert d65(560.0) == pytest.approx(1.0)  # the table's 100 at 560 nm, as a fraction
    # D65 from the daylight basis at its nominal CCT (6500 K with c2 corrected
    # from 1.4380e-2 to 1.4388e-2, CIE 15:2004 3.1), on the basis's scale (100
    # at 560 nm): CIE 15:2004 Table T.1 within 0.011 of 100.
    daylight = bandlight.daylight(6500 * 1.4388 / 1.4380)
    assert daylight(560.0) == pytest.approx(100.0)
    np.testing.assert_allclose(daylight.values, 100 * d65.values, atol=0.011)
    s0, s1, s2 = bandlight.daylight_basis()
    assert (s0.name, s1.name, s2.name) == ("S0", "S1", "S2")
    # Planck: normalised to 100 at 560 nm, peaking where Wien's law says.
    bb = bandlight.planckian(5000, start=300, step=1, count=1200)
    assert bb(560.0) == pytest.approx(100.0)
    peak = bb.wavelengths[np.argmax(bb.values)]
    assert peak == pytest.approx(2.897771955e-3 / 5000 * 1e9, abs=1.0)
    np.testing.assert_array_equal(bandlight.illuminant("3200K").values,
                                  bandlight.illuminant("BB3200").values)
    np.testing.assert_allclose(bandlight.illuminant("3200K").values,
                               bandlight.planckian(3200).values, rtol=1e-12)
    with pytest.raises(ValueError, match="unknown illuminant 'D99x'"):
        bandlight.illuminant("D99x")


def test_matching_functions():
    x, y, z = bandlight.cmf()
    assert (x.name, y.name, z.name) == ("x_bar", "y_bar", "z_bar")
    assert (y.start, y.end, y.step) == (360.0, 830.0, 5.0)
    assert y(555.0) == pytest.approx(1.0)
    # The rectangle-rule y_bar integral over 360-830 nm at 5 nm.
    assert y.sum() == pytest.approx(y.values.sum() * 5.0)
    assert y.sum() == pytest.approx(106.857, abs=1e-3)
    x10, y10, _ = bandlight.cmf("1964")
    assert y10(555.0) != y(555.0)
    r, g, b = bandlight.cmf(set="ebu_rgb")
    assert (r.name, g.name, b.name) == ("r_bar", "g_bar", "b_bar")
    assert r.values.min() < 0  # EBU RGB matching functions have negative lobes
    with pytest.raises(ValueError, match="1931"):
        bandlight.cmf("1950")


def test_test_colour_samples_and_sets():
    tcs = bandlight.reflectances("TCS")
    assert [s.name for s in tcs] == [f"TCS{i:02d}" for i in range(1, 16)]
    assert bandlight.reflectances("tcs09")[0].name == "TCS09"
    assert (tcs[0].start, tcs[0].end) == (360.0, 830.0)
    assert [s.name for s in bandlight.reflectance_set("tcs09-15")] == [s.name for s in tcs[8:]]
    assert len(bandlight.reflectance_set("rawtoaces190")) == 190
    assert len(bandlight.reflectance_set("random")) == 100
    with pytest.raises(ValueError, match="unknown reflectance"):
        bandlight.reflectances("TCS16")


def test_file_spectra_read_as_the_command_reads_them(tmp_path):
    csv = tmp_path / "lamp.csv"
    csv.write_text("# a lamp and a filter\nnm,lamp,filter\n"
                   + "".join(f"{w},{1 + (w - 380) / 400},{0.5}\n" for w in range(380, 785, 5)))
    spectra = bandlight.read_spectra(csv)
    assert [s.name for s in spectra] == ["lamp", "filter"]
    np.testing.assert_allclose(spectra[1].values, 0.5)
    # The same through parse_spectra.
    again = bandlight.parse_spectra(csv.read_text(), "lamp.csv")
    np.testing.assert_array_equal(again[0].values, spectra[0].values)
    # As an illuminant: the command's XYZ of its white.
    by_cli = cli_json("xyz", "--illuminant", csv, "--json")
    np.testing.assert_allclose(bandlight.xyz(str(csv)), by_cli["white_XYZ"], rtol=1e-12)
    assert bandlight.illuminant(csv).name == "lamp"


def test_cgats_files():
    sp = pathlib.Path("/usr/share/color/argyll/ref")
    files = sorted(sp.glob("*.sp")) if sp.is_dir() else []
    if not files:
        pytest.skip("argyll-ref is not installed")
    for f in files[:5]:
        spectra = bandlight.read_spectra(f)
        assert spectra and all(len(s) >= 2 for s in spectra)


def test_notes_become_warnings():
    short = ROBUSTNESS_DATA / "grey_400_700.csv"
    with pytest.warns(bandlight.NoteWarning, match="400"):
        grey = bandlight.reflectances(short)
    assert grey[0].name == "grey400_700"
