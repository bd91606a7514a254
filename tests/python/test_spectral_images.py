# SPDX-License-Identifier: BSD-3-Clause
"""Spectral images: files written here in each layout (Fichet 2021 emissive
and reflective, pbrt-v4 buckets in half float, named channels), read by
`bandlight spectral` and by the module, against independent numpy
integration; renders written with `render --spectra` and read back; bad
files refused with one line and nothing written."""

import csv
import json
import shutil

import numpy as np
import OpenImageIO as oiio
import pytest

import bandlight
from conftest import SCENES, cli_error, run_cli

GRID = np.arange(380.0, 781.0, 5.0)


def fichet_name(prefix, nm):
    return f"{prefix}.{nm:.6f}".replace(".", ",", 2).replace(",", ".", 1) + "nm"


def write_exr(path, channels, names, pixel_type="float", attributes=()):
    h, w, n = channels.shape
    spec = oiio.ImageSpec(w, h, n, pixel_type)
    spec.channelnames = tuple(names)
    for key, value in attributes:
        spec.attribute(key, value)
    out = oiio.ImageOutput.create(str(path))
    assert out.open(str(path), spec), oiio.geterror()
    assert out.write_image(np.ascontiguousarray(channels, dtype=np.float32))
    out.close()


def read(path):
    i = oiio.ImageInput.open(str(path))
    px = i.read_image("float")
    names = i.spec().channelnames
    spec = i.spec()
    i.close()
    return px, names, spec


def cmf_on(wavelengths):
    x, y, z = bandlight.cmf("1931")
    return np.stack([x(wavelengths), y(wavelengths), z(wavelengths)])


def xyz_to_acescg(xyz):
    return xyz @ np.linalg.inv(bandlight.rgb_to_xyz_matrix("acescg")).T


def tcs_block():
    """TCS01–TCS15 on GRID, as a 3 × 5 image of remittances."""
    tcs = bandlight.reflectances("TCS")
    return np.stack([s(GRID) for s in tcs]).reshape(3, 5, len(GRID))


def test_fichet_emissive_file_integrates_as_pbrt_does(tmp_path):
    # Radiance of the TCS under F11, point samples at 5 nm: XYZ =
    # Σ L·cmf·Δλ / Σ ȳ·Δλ (the constant spectrum 1 has Y = 1).
    f11 = bandlight.illuminant("F11")(GRID)
    radiance = (tcs_block() * f11).astype(np.float32)
    names = [fichet_name("S0", nm) for nm in GRID]
    write_exr(tmp_path / "shot.exr", radiance, names,
              attributes=[("spectralLayoutVersion", "1.0"), ("emissiveUnits", "W.m^-2.sr^-1")])
    p = run_cli("spectral", tmp_path / "shot.exr", tmp_path / "rgb.exr")
    assert "81 emissive samples 380-780 nm (Fichet 2021)" in p.stdout
    assert "integrated, lit, acescg" in p.stdout
    assert "nothing is known to balance" in p.stderr or "no light is known" in p.stderr
    rgb, names_out, spec = read(tmp_path / "rgb.exr")
    assert names_out == ("R", "G", "B")
    assert spec.get_string_attribute("colorInteropID") == "lin_ap1_scene"
    cmf = cmf_on(GRID)
    expected = xyz_to_acescg(radiance.astype(np.float64) @ cmf.T / cmf[1].sum())
    np.testing.assert_allclose(rgb, expected, rtol=2e-6, atol=1e-7)
    # The module reads the same file and integrates it the same way.
    wavelengths, spectra, kind, layout = bandlight.read_spectral_image(tmp_path / "shot.exr")
    np.testing.assert_allclose(wavelengths, GRID)
    np.testing.assert_array_equal(spectra, radiance)
    assert kind == "emissive" and "Fichet 2021" in layout
    with pytest.warns(bandlight.NoteWarning):
        mem = bandlight.spectral_to_rgb(spectra, wavelengths)
    np.testing.assert_array_equal(mem, rgb)


def test_reflective_file_under_d65_equals_xyz_of_the_remittances(tmp_path):
    # The layout's T channels on D65's own 5 nm grid (300–830 nm): the
    # CIE sum X = Σ S β x̄ Δλ / Σ S ȳ Δλ, as `xyz` computes it (Y = 100).
    d65 = bandlight.illuminant("D65")
    grid = d65.wavelengths
    tcs = bandlight.reflectances("TCS")
    remittance = np.stack([s.extended(grid[0], grid[-1])(grid) for s in tcs])
    remittance = remittance.reshape(3, 5, len(grid)).astype(np.float32)
    write_exr(tmp_path / "tcs.exr", remittance, [fichet_name("T", nm) for nm in grid],
              attributes=[("spectralLayoutVersion", "1.0")])
    run_cli("spectral", tmp_path / "tcs.exr", tmp_path / "rgb.exr", "--to", "D65",
            "--plates", "lit")
    rgb, _, _ = read(tmp_path / "rgb.exr")
    xyz = np.stack([bandlight.xyz("D65", s) for s in tcs]) / 100.0
    np.testing.assert_allclose(rgb.reshape(-1, 3), xyz_to_acescg(xyz), rtol=1e-5, atol=1e-6)
    # Balanced plates: D65's white maps onto ACEScg's white (1, 1, 1).
    white = np.ones((1, 2, len(grid)), np.float32)
    write_exr(tmp_path / "white.exr", white, [fichet_name("T", nm) for nm in grid])
    run_cli("spectral", tmp_path / "white.exr", tmp_path / "w.exr", "--to", "D65")
    np.testing.assert_allclose(read(tmp_path / "w.exr")[0], 1.0, atol=2e-6)
    assert "--to" in cli_error("spectral", tmp_path / "tcs.exr", tmp_path / "x.exr")


def test_pbrt_buckets_in_half_float(tmp_path):
    # pbrt-v4's spectral film: 16 buckets over 360–830 nm named by their
    # centres to 3 decimals, half float, R, G, B beside. Each holds the mean
    # over its bucket: the weights are the matching functions integrated
    # over each bucket.
    edges = np.linspace(360.0, 830.0, 17)
    centres = 0.5 * (edges[1:] + edges[:-1])
    names = ["R", "G", "B"] + ["S0." + f"{c:.3f}".replace(".", ",") + "nm" for c in centres]
    rng = np.random.default_rng(3)
    buckets = rng.uniform(0.0, 2.0, (4, 6, 16)).astype(np.float16).astype(np.float32)
    data = np.concatenate([np.zeros((4, 6, 3), np.float32), buckets], axis=2)
    write_exr(tmp_path / "pbrt.exr", data, names, pixel_type="half",
              attributes=[("spectralLayoutVersion", "1.0"), ("emissiveUnits", "W.m^-2.sr^-1")])
    p = run_cli("spectral", tmp_path / "pbrt.exr", tmp_path / "rgb.exr")
    assert "16 emissive buckets 360-830 nm (pbrt-v4 spectral film)" in p.stdout
    # Independent: the matching functions' linear interpolant integrated over
    # each bucket on a 0.01 nm grid.
    fine = np.arange(360.0, 830.0 + 1e-9, 0.01)
    cmf = cmf_on(fine)
    weights = np.stack([np.trapz(cmf[:, (fine >= a - 1e-9) & (fine <= b + 1e-9)],
                                 fine[(fine >= a - 1e-9) & (fine <= b + 1e-9)], axis=1)
                        for a, b in zip(edges[:-1], edges[1:])], axis=1)
    expected = xyz_to_acescg(buckets.astype(np.float64) @ weights.T / weights[1].sum())
    np.testing.assert_allclose(read(tmp_path / "rgb.exr")[0], expected, rtol=1e-4, atol=1e-5)


def test_named_channels_with_a_csv_of_wavelengths(tmp_path):
    # Mitsuba 3's specfilm names channels after its response functions.
    wavelengths = {"band1_blue": 450.0, "band2_green": 550.0, "band3_red": 650.0,
                   "band0_violet": 400.0}
    with open(tmp_path / "bands.csv", "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(["channel", "wavelength_nm"])
        for k, v in wavelengths.items():
            w.writerow([k, v])
    rng = np.random.default_rng(4)
    values = rng.uniform(0.0, 1.0, (3, 4, 4)).astype(np.float32)
    write_exr(tmp_path / "named.exr", values, list(wavelengths))
    run_cli("spectral", tmp_path / "named.exr", tmp_path / "a.exr", "--channel-wavelengths",
            tmp_path / "bands.csv")
    # The same as a Fichet file of those wavelengths, and as --channel.
    write_exr(tmp_path / "fichet.exr", values, [fichet_name("S0", nm) for nm in wavelengths.values()])
    run_cli("spectral", tmp_path / "fichet.exr", tmp_path / "b.exr")
    run_cli("spectral", tmp_path / "named.exr", tmp_path / "c.exr",
            *sum([["--channel", f"{k}={v}"] for k, v in wavelengths.items()], []))
    a = read(tmp_path / "a.exr")[0]
    np.testing.assert_array_equal(a, read(tmp_path / "b.exr")[0])
    np.testing.assert_array_equal(a, read(tmp_path / "c.exr")[0])
    assert np.abs(a).max() > 0.01
    # Irregular grid (400, 450, 550, 650): point samples weighted by their cells.
    grid = np.array(sorted(wavelengths.values()))
    edges = np.concatenate([[grid[0] - (grid[1] - grid[0]) / 2], (grid[1:] + grid[:-1]) / 2,
                            [grid[-1] + (grid[-1] - grid[-2]) / 2]])
    order = np.argsort(list(wavelengths.values()))
    cmf = cmf_on(grid) * np.diff(edges)
    expected = xyz_to_acescg(values[..., order].astype(np.float64) @ cmf.T / cmf[1].sum())
    np.testing.assert_allclose(a, expected, rtol=1e-5, atol=1e-6)
    # The module takes the same mapping.
    wl, spectra, kind, _ = bandlight.read_spectral_image(tmp_path / "named.exr",
                                                         channels=wavelengths)
    np.testing.assert_allclose(wl, grid)
    np.testing.assert_array_equal(spectra, values[..., order])


def test_channels_that_are_not_samples_never_enter_the_integration(tmp_path):
    # band_07x sorts between band_07 and band_08; NaN there once made every
    # pixel NaN (0 x NaN in a dot product over the whole channel range).
    names = [f"band_{i:02d}" for i in range(16)]
    wavelengths = {n: 400.0 + 20.0 * i for i, n in enumerate(names)}
    with open(tmp_path / "bands.csv", "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(["channel", "wavelength_nm"])
        w.writerows(wavelengths.items())
    values = np.random.default_rng(7).uniform(0.0, 1.0, (4, 4, 16)).astype(np.float32)
    write_exr(tmp_path / "clean.exr", values, names)
    extra = np.full((4, 4, 2), np.nan, dtype=np.float32)
    extra[1:, :, 1] = 0.5  # alpha: NaN in the first row only
    write_exr(tmp_path / "dirty.exr", np.concatenate([values, extra], axis=-1),
              names + ["band_07x", "A"])
    for name in ("clean", "dirty"):
        run_cli("spectral", tmp_path / f"{name}.exr", tmp_path / f"{name}_rgb.exr",
                "--channel-wavelengths", tmp_path / "bands.csv")
    clean = read(tmp_path / "clean_rgb.exr")[0]
    dirty, channels, _ = read(tmp_path / "dirty_rgb.exr")
    assert channels == ("R", "G", "B", "A")
    # (the same sums, in another order of SIMD lanes: to float rounding)
    np.testing.assert_allclose(dirty[..., :3], clean, rtol=1e-6, atol=1e-7)
    assert np.isfinite(dirty[..., :3]).all() and np.abs(clean).max() > 0.01
    # Alpha is carried as it is, as apply carries it: NaN included.
    assert np.isnan(dirty[0, :, 3]).all()
    np.testing.assert_array_equal(dirty[1:, :, 3], 0.5)


def test_render_spectra_round_trip_and_relight(tmp_path):
    scene = SCENES / "materials_A.yaml"
    run_cli("render", scene, "--mode", "spectral", "-o", tmp_path / "rgb.exr")
    run_cli("render", scene, "--mode", "spectral", "--spectra", "-o", tmp_path / "spec.exr")
    spec_px, names, spec = read(tmp_path / "spec.exr")
    assert spec.get_string_attribute("spectralLayoutVersion") == "1.0"
    assert spec.get_string_attribute("emissiveUnits") == "W.m^-2.sr^-1"
    assert names[:3] == ("B", "G", "R") or "R" in names
    rgb = read(tmp_path / "rgb.exr")[0]
    # R, G, B beside the spectrum are the RGB render.
    for c, n in enumerate("RGB"):
        np.testing.assert_array_equal(spec_px[..., names.index(n)], rgb[..., c])
    # Integrated without a relight: the RGB render, to 1e-5 of the brightest pixel.
    run_cli("spectral", tmp_path / "spec.exr", tmp_path / "back.exr")
    back = read(tmp_path / "back.exr")[0]
    assert np.abs(back - rgb).max() <= 1e-5 * np.abs(rgb).max()
    # Relit from A to D65 (lit): the same scene rendered under D65, up to the
    # two renders' light scales (each light's largest band mean = 1, against
    # relighting's S2 at S1's luminance).
    run_cli("spectral", tmp_path / "spec.exr", tmp_path / "relit.exr", "--from", "A",
            "--to", "D65", "--plates", "lit")
    run_cli("render", SCENES / "materials_D65.yaml", "--mode", "spectral", "-o",
            tmp_path / "d65.exr")
    relit = read(tmp_path / "relit.exr")[0]
    d65 = read(tmp_path / "d65.exr")[0]
    a, e = bandlight.illuminant("A"), bandlight.illuminant("D65")
    y = bandlight.cmf("1931")[1]
    wl = np.array([float(n[3:-2].replace(",", ".")) for n in names if n.startswith("S0.")])
    lum = lambda s: np.sum(s(wl) * y(wl))  # noqa: E731  (S2 scaled to S1's luminance on the grid)
    scale = (1 / a.band_means().max()) * lum(a) / lum(e) / (1 / e.band_means().max())
    assert np.abs(relit - d65 * scale).max() <= 1e-5 * np.abs(relit).max()


@pytest.mark.parametrize("names,values,message", [
    (["S0.abcnm", "S0.500nm"], None, "channel 'S0.abcnm' is not a spectral channel name"),
    (["S0.500nm", "S0.0,6um"], None, "mixed units"),
    (["S0.500nm", "S0.500,0nm"], None, "have the same wavelength"),
    (["R", "G", "S0.500nm"], None, "is its only spectral channel"),
    (["S1.500nm", "S1.600nm"], None, "S1-S3) but the image has no S0 channels"),
    (["T.400nm.500nm", "T.500nm"], None, "is bi-spectral"),
    (["S0.500nm", "S0.600nm"], np.nan, "channel 'S0.600,000000nm' is NaN"),
    (["S0.500nm", "S0.600nm"], np.inf, "is infinite"),
    (["S0.500nm", "S0.600nm"], -1.0, "is negative"),
])
def test_bad_spectral_files_are_refused_with_one_line(tmp_path, names, values, message):
    data = np.ones((2, 2, len(names)), np.float32)
    if values is not None:
        data[1, 1, 1] = values
        names = [fichet_name("S0", 500), fichet_name("S0", 600)]
    write_exr(tmp_path / "bad.exr", data, names)
    err = cli_error("spectral", tmp_path / "bad.exr", tmp_path / "out.exr")
    assert str(tmp_path / "bad.exr") in err and message in err, err
    assert not (tmp_path / "out.exr").exists()
    with pytest.raises(ValueError, match="bad.exr"):
        bandlight.read_spectral_image(tmp_path / "bad.exr")


def test_lying_headers_and_huge_channel_counts_are_refused(tmp_path):
    data = np.ones((1, 1, 2), np.float32)
    write_exr(tmp_path / "v2.exr", data, ["S0.500nm", "S0.600nm"],
              attributes=[("spectralLayoutVersion", "2.0")])
    assert "spectralLayoutVersion is '2.0'" in cli_error("spectral", tmp_path / "v2.exr",
                                                          tmp_path / "o.exr")
    write_exr(tmp_path / "lie.exr", data, ["T.500nm", "T.600nm"],
              attributes=[("emissiveUnits", "W.m^-2.sr^-1")])
    assert "says emissiveUnits but its spectral channels are reflective" in cli_error(
        "spectral", tmp_path / "lie.exr", tmp_path / "o.exr", "--to", "D65")
    many = np.ones((1, 1, 10000), np.float32)
    write_exr(tmp_path / "many.exr", many, [f"S0.{380 + i * 0.04:.2f}nm" for i in range(10000)])
    assert "10000 channels" in cli_error("spectral", tmp_path / "many.exr", tmp_path / "o.exr")
    assert not (tmp_path / "o.exr").exists()


def test_accuracy_on_an_image_of_known_remittances_equals_the_csv(tmp_path):
    tcs = bandlight.reflectances("TCS")
    remittance = tcs_block()
    with open(tmp_path / "tcs.csv", "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(["wavelength_nm"] + [f"p{x}_{y}" for y in range(3) for x in range(5)])
        for i, nm in enumerate(GRID):
            # The values the image holds: float32.
            w.writerow([f"{nm:g}"] + [repr(float(np.float32(v))) for v in
                                      remittance.reshape(15, -1)[:, i]])
    write_exr(tmp_path / "tcs.exr", remittance, [fichet_name("T", nm) for nm in GRID])
    common = ["--methods", "bradford,rootpoly", "--ideal-only", "--no-cost"]
    img = json.loads(run_cli("accuracy", "--image", tmp_path / "tcs.exr", "--from", "A", "--to",
                             "D65", "--json", "-", *common).stdout)
    ref = json.loads(run_cli("accuracy", "--reflectances", tmp_path / "tcs.csv", "--illuminants",
                             "A,D65", "--json", "-", *common).stdout)
    rows = lambda d, s: {(r["method"], r["from"], r["to"], r["plates"], r["exposure"]): r  # noqa: E731
                         for r in d["rows"] if r["set"] == s}
    a, b = rows(img, str(tmp_path / "tcs.exr")), rows(ref, str(tmp_path / "tcs.csv"))
    # The image is measured for the change it was given, A -> D65, not back.
    assert {k[1:3] for k in a} == {("A", "D65")}
    b = {k: v for k, v in b.items() if k[1:3] == ("A", "D65")}
    # two methods, lit and balanced plates at least, seven exposures
    assert a.keys() == b.keys() and len(a) >= 2 * 2 * 7
    for k in a:
        for stat in ("mean", "p95", "max"):
            assert a[k][stat] == pytest.approx(b[k][stat], abs=1e-6), (k, stat)


def test_accuracy_heatmaps_of_a_render(tmp_path):
    run_cli("render", SCENES / "tcs_spectral_F11.yaml", "--spectra", "-o", tmp_path / "spec.exr")
    p = run_cli("accuracy", "--image", tmp_path / "spec.exr", "--from", "F11", "--to", "D65",
                "--methods", "none,bradford,rootpoly", "--ideal-only", "--no-cost",
                "--plates", "lit", "--heatmaps", tmp_path / "maps")
    for m in ("none", "bradford", "rootpoly"):
        exr = tmp_path / "maps" / f"spec_{m}_dE00.exr"
        png = tmp_path / "maps" / f"spec_{m}_dE00.png"
        assert exr.exists() and png.exists()
        assert png.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
        assert f"accuracy: {m} over the image: CIEDE2000 mean" in p.stderr
    assert not (tmp_path / "maps" / "spec_spectral_dE00.exr").exists()
    none = read(tmp_path / "maps" / "spec_none_dE00.exr")[0]
    brad = read(tmp_path / "maps" / "spec_bradford_dE00.exr")[0]
    # On lit plates, doing nothing about the change of light is far worse
    # than Bradford.
    assert none.mean() > 3 * brad.mean() > 0
    # The rows name the file.
    assert str(tmp_path / "spec.exr") in p.stdout


def test_accuracy_heatmaps_are_one_set_with_the_json_and_never_share_a_name(tmp_path):
    # Two renders named alike in two shot folders: each keeps its own maps.
    for shot in ("shotA", "shotB"):
        (tmp_path / shot).mkdir()
    run_cli("render", SCENES / "tcs_spectral_F11.yaml", "--spectra", "-o",
            tmp_path / "shotA" / "beauty.exr")
    shutil.copy(tmp_path / "shotA" / "beauty.exr", tmp_path / "shotB" / "beauty.exr")
    common = ["--from", "F11", "--to", "D65", "--methods", "bradford", "--ideal-only",
              "--no-cost", "--plates", "lit"]
    maps = tmp_path / "maps"
    run_cli("accuracy", "--image", tmp_path / "shotA" / "beauty.exr", "--image",
            tmp_path / "shotB" / "beauty.exr", "--heatmaps", maps, *common)
    assert sorted(p.name for p in maps.iterdir()) == [
        "shotA_beauty_bradford_dE00.exr", "shotA_beauty_bradford_dE00.png",
        "shotB_beauty_bradford_dE00.exr", "shotB_beauty_bradford_dE00.png"]
    before = {p.name: p.read_bytes() for p in maps.iterdir()}
    # A run that fails on its JSON (into a folder that is not there) is
    # refused before any work, and the earlier maps are as they were.
    p = run_cli("accuracy", "--image", tmp_path / "shotA" / "beauty.exr", "--heatmaps", maps,
                "--json", tmp_path / "missing" / "x.json", *common, check=False)
    assert p.returncode == 2 and p.stderr.count("\n") == 1, p.stderr
    assert {p.name: p.read_bytes() for p in maps.iterdir()} == before


def test_an_emissive_image_lit_by_a_known_light_is_balanced_from_it(tmp_path):
    # The white reflector under A, given --from A alone: integrated, then
    # white-balanced from A's white to ACEScg's, so R = G = B.
    a = bandlight.illuminant("A")(GRID)
    white = np.broadcast_to(a, (2, 3, len(GRID))).astype(np.float32)
    write_exr(tmp_path / "white_A.exr", white, [fichet_name("S0", nm) for nm in GRID])
    p = run_cli("spectral", tmp_path / "white_A.exr", tmp_path / "w.exr", "--from", "A")
    assert "integrated, lit by A, balanced (cat02)" in p.stdout
    rgb = read(tmp_path / "w.exr")[0]
    np.testing.assert_allclose(rgb, rgb[..., 1:2].repeat(3, axis=-1), rtol=1e-6)
    # Lit, it keeps A's orange.
    run_cli("spectral", tmp_path / "white_A.exr", tmp_path / "lit.exr", "--from", "A",
            "--plates", "lit")
    lit = read(tmp_path / "lit.exr")[0]
    assert lit[0, 0, 0] > 1.5 * lit[0, 0, 2]
