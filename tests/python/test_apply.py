# SPDX-License-Identifier: BSD-3-Clause
"""bandlight.apply: image files and frame sequences, as `bandlight apply`."""

import numpy as np
import OpenImageIO as oiio
import pytest

import bandlight
from conftest import acescg_spec, cli_error, run_cli


def write_plate(path, seed=1, channels=4):
    rng = np.random.default_rng(seed)
    px = rng.uniform(0.0, 4.0, (12, 20, channels)).astype(np.float32)
    if channels == 4:
        px[..., 3] = 0.5
    out = oiio.ImageOutput.create(str(path))
    assert out.open(str(path), acescg_spec(20, 12, channels))
    assert out.write_image(px)
    out.close()
    return px


def read(path):
    return oiio.ImageInput.open(str(path)).read_image("float")


def test_apply_a_relight_equals_the_command_and_the_relighter(tmp_path):
    px = write_plate(tmp_path / "plate.exr")
    result = bandlight.apply(tmp_path / "plate.exr", tmp_path / "py.exr", src="A", dst="D65")
    assert result["applied"] == "bradford_A_to_D65" and result["frames"] == 1
    run_cli("apply", tmp_path / "plate.exr", tmp_path / "cli.exr", "--from", "A", "--to", "D65")
    out = read(tmp_path / "py.exr")
    np.testing.assert_array_equal(out, read(tmp_path / "cli.exr"))
    np.testing.assert_array_equal(out[..., 3], px[..., 3])  # alpha passes through
    # The same pixels as the in-memory relighter (to float rounding of OCIO's matrix).
    mem = bandlight.Relighter("A", "D65", "bradford").apply(px[..., :3].copy())
    np.testing.assert_allclose(out[..., :3], mem, rtol=2e-6, atol=1e-7)


def test_apply_a_sequence_and_a_look(tmp_path):
    for f in (1001, 1002, 1003):
        write_plate(tmp_path / f"plate.{f}.exr", seed=f, channels=3)
    r = bandlight.apply(tmp_path / "plate.####.exr", tmp_path / "out.####.exr",
                        frames="1001-1003", src="F11", dst="D65", method="rootpoly")
    assert r["frames"] == 3 and r["applied"].endswith("(native)")
    run_cli("apply", tmp_path / "plate.####.exr", tmp_path / "cli.####.exr", "--frames",
            "1001-1003", "--from", "F11", "--to", "D65", "--method", "rootpoly")
    for f in (1001, 1002, 1003):
        np.testing.assert_array_equal(read(tmp_path / f"out.{f}.exr"),
                                      read(tmp_path / f"cli.{f}.exr"))
    config = tmp_path / "config"
    bandlight.config(config, illuminants="A,D65", methods=["band3"])
    r = bandlight.apply(tmp_path / "plate.1001.exr", tmp_path / "look.exr",
                        look="band3_A_to_D65", config=config)
    assert r["applied"] == "look band3_A_to_D65" and r["frames"] == 1


def test_apply_errors_name_python_parameters(tmp_path):
    write_plate(tmp_path / "plate.exr")
    with pytest.raises(ValueError) as e:
        bandlight.apply(tmp_path / "plate.exr", tmp_path / "o.exr")
    assert str(e.value) == "give look=NAME config=DIR, or src=S1 dst=S2 [method=M]"
    assert cli_error("apply", tmp_path / "plate.exr", tmp_path / "o.exr") == \
        "give --look NAME --config DIR, or --from S1 --to S2 [--method M]"
    with pytest.raises(ValueError, match="give frames=FIRST-LAST"):
        bandlight.apply(tmp_path / "p.####.exr", tmp_path / "o.####.exr", src="A", dst="D65")
    with pytest.raises(ValueError, match="threads must be 0"):
        bandlight.apply(tmp_path / "plate.exr", tmp_path / "o.exr", src="A", dst="D65",
                        threads=-1)
    # A missing input is a file error, as docs/python.md says, not a bad value.
    with pytest.raises(FileNotFoundError, match="no-such.exr"):
        bandlight.apply(tmp_path / "no-such.exr", tmp_path / "o.exr", src="A", dst="D65")
    assert not (tmp_path / "o.exr").exists()


def test_apply_skips_existing_frames_and_keeps_going(tmp_path):
    for f in range(1, 5):
        write_plate(tmp_path / f"p.{f:04d}.exr", seed=f)
    (tmp_path / "p.0003.exr").write_bytes(b"not an image")
    r = bandlight.apply(tmp_path / "p.####.exr", tmp_path / "o.####.exr", frames="1-4",
                        src="A", dst="D65", keep_going=True)
    assert r["frames"] == 3 and r["skipped"] == 0
    assert [f for f, _ in r["failed"]] == [3] and "p.0003.exr" in r["failed"][0][1]
    (tmp_path / "o.0002.exr").unlink()
    r = bandlight.apply(tmp_path / "p.####.exr", tmp_path / "o.####.exr", frames="1,2,4",
                        src="A", dst="D65", skip_existing=True)
    assert r["frames"] == 1 and r["skipped"] == 2 and r["failed"] == []
    with pytest.raises(ValueError, match="p.0003.exr"):
        bandlight.apply(tmp_path / "p.####.exr", tmp_path / "x.####.exr", frames="1-4",
                        src="A", dst="D65")


def test_relighter_pickles_by_its_specification(tmp_path):
    import pickle
    training = bandlight.reflectances("TCS")
    for r in (bandlight.Relighter("A", "D65", "bradford"),
              bandlight.Relighter("F11", "D65", "rootpoly", plates="lit"),
              bandlight.Relighter(bandlight.illuminant("3200K"), "D65", "fit3x3",
                                  training=training)):
        again = pickle.loads(pickle.dumps(r))
        px = np.random.default_rng(2).uniform(0, 4, (64, 3)).astype(np.float32)
        np.testing.assert_array_equal(again.apply(px), r.apply(px))


def test_frame_sets_are_the_commands():
    assert bandlight.frame_set("1001-1005x2,1010") == [1001, 1003, 1005, 1010]
    with pytest.raises(ValueError, match="frame range"):
        bandlight.frame_set("5-1")
