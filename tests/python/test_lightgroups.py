# SPDX-License-Identifier: BSD-3-Clause
"""Light groups in memory: relight_light_groups relights each group of a dict
of arrays on its own and rebuilds the beauty with the residual, as
`bandlight apply --light-group` does to files."""

import pickle

import numpy as np
import pytest

import bandlight


def shot():
    rng = np.random.default_rng(7)
    key = rng.uniform(0.0, 2.0, (4, 5, 3)).astype(np.float32)
    fill = rng.uniform(0.0, 0.5, (4, 5, 3)).astype(np.float32)
    emission = np.zeros((4, 5, 3), np.float32)
    emission[1, 2] = (3.0, 2.0, 1.0)
    return key, fill, (key.astype(np.float64) + fill + emission).astype(np.float32)


def test_each_group_relit_as_relight_does_and_the_residual_kept():
    key, fill, beauty = shot()
    out = bandlight.relight_light_groups({"key": key, "fill": fill}, {"key": ("A", "D65")},
                                         beauty=beauty, method="rootpoly")
    expected = bandlight.relight(key, "A", "D65", "rootpoly", plates="lit")
    np.testing.assert_allclose(out["groups"]["key"], expected, rtol=1e-6, atol=1e-7)
    np.testing.assert_array_equal(out["groups"]["fill"], fill)
    residual = beauty.astype(np.float64) - key - fill
    np.testing.assert_allclose(out["beauty"], expected.astype(np.float64) + fill + residual,
                               rtol=1e-6, atol=1e-6)
    assert out["beauty"][1, 2, 0] == pytest.approx(expected[1, 2, 0] + fill[1, 2, 0] + 3.0,
                                                   rel=1e-6)
    # Plain dicts of arrays: they pickle, for Dask.
    back = pickle.loads(pickle.dumps(out))
    np.testing.assert_array_equal(back["beauty"], out["beauty"])


def test_identity_gives_the_beauty_back():
    key, fill, beauty = shot()
    out = bandlight.relight_light_groups({"key": key, "fill": fill},
                                         {"key": ("A", "A"), "fill": ("F11", "F11")},
                                         beauty=beauty, method="rootpoly")
    np.testing.assert_allclose(out["beauty"], beauty, rtol=1e-6, atol=1e-7)


def test_without_a_beauty_it_is_the_sum_of_the_groups():
    key, fill, _ = shot()
    out = bandlight.relight_light_groups({"key": key, "fill": fill}, {"fill": ("F11", "D50")})
    np.testing.assert_allclose(out["beauty"],
                               key.astype(np.float64) + out["groups"]["fill"], rtol=1e-6)


def test_bad_input_is_refused_naming_the_group():
    key, fill, beauty = shot()
    with pytest.raises(ValueError, match="which groups does not hold"):
        bandlight.relight_light_groups({"key": key}, {"rim": ("A", "D65")})
    with pytest.raises(ValueError, match="sum to more than the beauty"):
        bandlight.relight_light_groups({"key": key, "fill": fill}, {"key": ("A", "D65")},
                                       beauty=key)
    # NaN is guarded as every pixel path guards it: the result is finite.
    nan = fill.copy()
    nan[0, 1, 2] = np.nan
    relit = bandlight.relight_light_groups({"key": key, "fill": nan}, {"key": ("A", "D65")},
                                           beauty=beauty)
    assert np.isfinite(relit["beauty"]).all()
    assert all(np.isfinite(g).all() for g in relit["groups"].values())
    with pytest.raises(ValueError, match="same image's layer"):
        bandlight.relight_light_groups({"key": key, "fill": fill[:2]}, {"key": ("A", "D65")})


def test_render_and_apply_files_with_light_groups(tmp_path):
    from conftest import SCENES
    shot = tmp_path / "shot.exr"
    result = bandlight.render(SCENES / "two_lights.yaml", out=shot, light_groups=True,
                              mode="band3", preview=False)
    assert result["files"] == [str(shot)]
    relit = tmp_path / "relit.exr"
    with pytest.warns(bandlight.NoteWarning, match="2 light groups \\(key, fill\\), bandlight"):
        summary = bandlight.apply(shot, relit, light_groups={"key": ("A", "D65")},
                                  method="rootpoly")
    assert "key: rootpoly_A_to_D65" in summary["applied"]
    assert summary["frames"] == 1 and relit.is_file()
    with pytest.raises(ValueError, match="has no light group 'rim'"):
        bandlight.apply(shot, tmp_path / "bad.exr", light_groups={"rim": ("A", "D65")})
    assert not (tmp_path / "bad.exr").exists()


def test_spectral_light_groups_exact_and_named(tmp_path):
    from conftest import SCENES
    shot = tmp_path / "shot.exr"
    bandlight.render(SCENES / "two_lights.yaml", out=shot, light_groups=True, spectra=True,
                     preview=False)
    same = tmp_path / "same.exr"
    summary = bandlight.spectral(shot, same, light_groups={"key": ("A", "A"),
                                                           "fill": ("F11", "F11")})
    assert "light groups" in summary["applied"]
    integrated = tmp_path / "integrated.exr"
    bandlight.spectral(shot, integrated, plates="lit")
    with pytest.raises(ValueError, match="has no spectral light group 'rim'"):
        bandlight.spectral(shot, tmp_path / "bad.exr", light_groups={"rim": ("A", "D65")})
    with pytest.raises(ValueError, match="plates=lit"):
        bandlight.spectral(shot, tmp_path / "bad.exr", light_groups={"key": ("A", "D65")},
                           plates="balanced")
    assert not (tmp_path / "bad.exr").exists()
    assert same.is_file() and integrated.is_file()


def test_each_group_takes_a_method_of_its_own(tmp_path):
    # key=A:D65@rootpoly beside fill with --method bradford: each group as a
    # run with that group's method for every group gives it.
    from conftest import SCENES, run_cli
    shot = tmp_path / "shot.exr"
    bandlight.render(SCENES / "two_lights.yaml", out=shot, light_groups=True, mode="band3",
                     preview=False)

    def layers(path):
        import OpenImageIO as oiio
        i = oiio.ImageInput.open(str(path))
        px, names = i.read_image("float"), i.spec().channelnames
        i.close()
        return {n: px[..., c] for c, n in enumerate(names)}

    run_cli("apply", shot, tmp_path / "mixed.exr", "--light-group", "key=A:D65@rootpoly",
            "--light-group", "fill=F11:D50", "--method", "bradford")
    for method in ("rootpoly", "bradford"):
        run_cli("apply", shot, tmp_path / f"{method}.exr", "--light-group", "key=A:D65",
                "--light-group", "fill=F11:D50", "--method", method)
    mixed, rp, br = (layers(tmp_path / f"{n}.exr") for n in ("mixed", "rootpoly", "bradford"))
    for c in "RGB":
        np.testing.assert_array_equal(mixed[f"key.{c}"], rp[f"key.{c}"])
        np.testing.assert_array_equal(mixed[f"fill.{c}"], br[f"fill.{c}"])
    assert np.abs(rp["key.R"] - br["key.R"]).max() > 1e-4  # the methods differ here
    # Python takes the same as (src, dst, method).
    with pytest.warns(bandlight.NoteWarning, match="2 light groups"):
        bandlight.apply(shot, tmp_path / "py.exr", method="bradford",
                        light_groups={"key": ("A", "D65", "rootpoly"), "fill": ("F11", "D50")})
    py = layers(tmp_path / "py.exr")
    for name in mixed:
        np.testing.assert_array_equal(py[name], mixed[name])
    from conftest import cli_error
    assert "NAME=FROM:TO@METHOD" in cli_error("apply", shot, tmp_path / "bad.exr",
                                              "--light-group", "key=A:D65@")
    # A shot with many groups lists them in a file, one per line, the same.
    (tmp_path / "groups.txt").write_text("# the key's tungsten, by rootpoly\n"
                                         "key=A:D65@rootpoly\n\n  fill=F11:D50  \n")
    run_cli("apply", shot, tmp_path / "file.exr", "--light-group-file",
            tmp_path / "groups.txt", "--method", "bradford")
    from_file = layers(tmp_path / "file.exr")
    for name in mixed:
        np.testing.assert_array_equal(from_file[name], mixed[name])
    # A bad line is named by its file and line.
    (tmp_path / "bad.txt").write_text("key=A:D65\nfill=F11:\n")
    assert cli_error("apply", shot, tmp_path / "bad.exr", "--light-group-file",
                     tmp_path / "bad.txt").startswith(f"{tmp_path / 'bad.txt'}:2: ")
    (tmp_path / "empty.txt").write_text("# nothing\n")
    assert "lists no light group" in cli_error("apply", shot, tmp_path / "bad.exr",
                                               "--light-group-file", tmp_path / "empty.txt")
    assert not (tmp_path / "bad.exr").exists()


def test_the_python_face_takes_what_the_docs_show_and_names_its_mistakes(tmp_path):
    key, fill, beauty = shot()
    # (src, dst, method), as apply(light_groups=...) takes it.
    own = bandlight.relight_light_groups({"key": key, "fill": fill},
                                         {"key": ("A", "D65", "rootpoly")}, beauty=beauty)
    same = bandlight.relight_light_groups({"key": key, "fill": fill}, {"key": ("A", "D65")},
                                          beauty=beauty, method="rootpoly")
    np.testing.assert_array_equal(own["groups"]["key"], same["groups"]["key"])
    # A keyword a function does not take: one line, the nearest it does take.
    with pytest.raises(TypeError, match=r"takes no keyword metod= \(did you mean method=\?\)"):
        bandlight.relight_light_groups({"key": key}, {"key": ("A", "D65")}, metod="rootpoly")
    with pytest.raises(TypeError, match=r"takes no keyword metod= \(did you mean method=\?\)"):
        bandlight.apply(tmp_path / "nothing.exr", tmp_path / "x.exr", src="A", dst="D65",
                        metod="rootpoly")
    # frames= as a range or a list, as a string.
    from conftest import SCENES
    for f in (1001, 1002, 1003):
        bandlight.render(SCENES / "materials_A.yaml", out=tmp_path / f"in.{f}.exr",
                         preview=False)
    for i, frames in enumerate(("1001-1003", range(1001, 1004), [1001, 1002, 1003])):
        summary = bandlight.apply(tmp_path / "in.####.exr", tmp_path / f"out{i}.####.exr",
                                  frames=frames, src="A", dst="D65")
        assert summary["frames"] == 3
    with pytest.raises(TypeError, match="frames= takes"):
        bandlight.apply(tmp_path / "in.####.exr", tmp_path / "x.####.exr", frames=3.5,
                        src="A", dst="D65")
