# SPDX-License-Identifier: BSD-3-Clause
"""Configs and LUT files, against what the command writes."""

import filecmp

import numpy as np
import PyOpenColorIO as OCIO
import pytest

import bandlight
from conftest import cli_error, run_cli


def same_tree(a, b):
    cmp = filecmp.dircmp(a, b)
    files = [f for f in cmp.common_files]
    match, mismatch, errors = filecmp.cmpfiles(a, b, files, shallow=False)
    assert not cmp.left_only and not cmp.right_only, (cmp.left_only, cmp.right_only)
    assert not mismatch and not errors, (mismatch, errors)
    for sub in cmp.common_dirs:
        same_tree(a / sub, b / sub)
    return len(match)


def test_config_is_a_pyopencolorio_config():
    config = bandlight.config(illuminants=["A", "D65", "F11"], methods=["bradford", "band3"])
    assert type(config) is OCIO.Config
    config.validate()
    looks = sorted(look.getName() for look in config.getLooks())
    assert len(looks) == 3 * 2 * 2
    assert "band3_F11_to_D65" in looks and "bradford_A_to_D65" in looks
    assert config.getNamedTransform("relight_band3_F11_to_D65") is not None
    # The look applies to pixels through PyOpenColorIO.
    t = OCIO.LookTransform(src="ACEScg", dst="ACEScg", looks="bradford_A_to_D65")
    cpu = config.getProcessor(t).getDefaultCPUProcessor()
    assert cpu.applyRGB([0.18, 0.18, 0.18]) is not None


def test_written_config_equals_the_commands(tmp_path):
    py_dir, cli_dir = tmp_path / "py", tmp_path / "cli"
    config = bandlight.config(py_dir, illuminants="A,D65,F11", methods=["bradford", "band3-wp"],
                              working_space="lin-rec709")
    run_cli("config", "--out", cli_dir, "--illuminants", "A,D65,F11", "--methods",
            "bradford,band3-wp", "--working-space", "lin-rec709")
    assert same_tree(py_dir, cli_dir) == 1
    assert config.getWorkingDir().rstrip("/") == str(py_dir)
    again = OCIO.Config.CreateFromFile(str(py_dir / "config.ocio"))
    assert len(list(again.getLooks())) == len(list(config.getLooks())) == 12


def test_default_config_is_the_commands_byte_for_byte(tmp_path):
    # bandlight config --out A and bandlight.config("B"): one job, one default
    # request, the same file (tests/jobs checks a C++ host's call too).
    bandlight.config(tmp_path / "B")
    run_cli("config", "--out", tmp_path / "A")
    written = (tmp_path / "B" / "config.ocio").read_bytes()
    assert written and written == (tmp_path / "A" / "config.ocio").read_bytes()


def test_non_linear_looks_write_their_luts(tmp_path):
    py_dir, cli_dir = tmp_path / "py", tmp_path / "cli"
    config = bandlight.config(py_dir, illuminants=["A", "D65"], methods=["rootpoly"],
                              lut_size=9)
    run_cli("config", "--out", cli_dir, "--illuminants", "A,D65", "--methods", "rootpoly",
            "--lut-size", "9")
    assert same_tree(py_dir, cli_dir) == 1
    assert sorted(p.name for p in (py_dir / "luts").iterdir()) == [
        "rootpoly_A_to_D65.clf", "rootpoly_D65_to_A.clf"]
    # The returned config finds its LUT files.
    t = OCIO.LookTransform(src="ACEScg", dst="ACEScg", looks="rootpoly_A_to_D65")
    rgb = config.getProcessor(t).getDefaultCPUProcessor().applyRGB([0.2, 0.3, 0.4])
    assert np.all(np.isfinite(rgb))
    with pytest.raises(ValueError, match="give out=DIR"):
        bandlight.config(illuminants=["A", "D65"], methods=["rootpoly"], lut_size=9)


def test_extending_a_studio_config_equals_the_command(tmp_path):
    base = tmp_path / "base"
    run_cli("config", "--out", base, "--illuminants", "A,D65", "--methods", "bradford",
            "--working-space", "rec2020")
    py_dir, cli_dir, obj_dir = tmp_path / "py", tmp_path / "cli", tmp_path / "obj"
    bandlight.config(py_dir, base=base / "config.ocio", illuminants=["F2", "F11"],
                     methods=["cat02"])
    run_cli("config", "--out", cli_dir, "--base", base / "config.ocio", "--illuminants",
            "F2,F11", "--methods", "cat02")
    assert same_tree(py_dir, cli_dir) == 1
    # A PyOpenColorIO.Config read from the file is the same base.
    base_config = OCIO.Config.CreateFromFile(str(base / "config.ocio"))
    extended = bandlight.config(obj_dir, base=base_config, illuminants=["F2", "F11"],
                                methods=["cat02"])
    assert (obj_dir / "config.ocio").read_text() == (cli_dir / "config.ocio").read_text()
    assert extended.getLook("bradford_A_to_D65") is not None  # the base's look, kept
    assert extended.getLook("cat02_F2_to_F11") is not None
    space, evidence = bandlight.identify_scene_linear(base / "config.ocio")
    assert space == "rec2020" and evidence


def test_config_errors_are_the_commands(tmp_path):
    missing = tmp_path / "nowhere" / "config.ocio"
    with pytest.raises(FileNotFoundError) as e:
        bandlight.config(tmp_path / "out", base=missing)
    assert str(e.value) == cli_error("config", "--out", tmp_path / "out2", "--base", missing)
    with pytest.raises(ValueError) as e:
        bandlight.config(illuminants=["A"])
    with pytest.raises(ValueError) as e:
        bandlight.config(methods=["bogus"])
    assert str(e.value) == cli_error("config", "--out", tmp_path / "x", "--methods", "bogus")
    # An output folder that cannot be made (a file is in the way).
    (tmp_path / "file").write_text("")
    with pytest.raises(NotADirectoryError, match="is not a folder"):
        bandlight.config(tmp_path / "file" / "sub")


@pytest.mark.parametrize("method, fmt, size", [
    ("band3", "clf", None),        # the exact matrix
    ("band3", "ctf", 9),           # baked: shaper + 9^3 LUT + inverse shaper
    ("bradford", "cube", 9),       # the LUT and its companion shaper
    ("rootpoly", "spi3d", 9),      # non-linear: baked from the native fit
    ("band3-wp", "resolve_cube", 5),
])
def test_luts_equal_the_commands(tmp_path, method, fmt, size):
    ext = {"resolve_cube": "cube"}.get(fmt, fmt)
    # The same file name in two folders: a .cube names its companion shaper.
    (tmp_path / "py").mkdir()
    (tmp_path / "cli").mkdir()
    py_path, cli_path = tmp_path / "py" / f"lut.{ext}", tmp_path / "cli" / f"lut.{ext}"
    extra = {"shaper": "none"} if fmt == "resolve_cube" else {}
    result = bandlight.lut(py_path, "A", "F2", method, format=fmt, size=size, **extra)
    args = ["--size", size] if size else []
    args += ["--shaper", "none"] if extra else []
    run_cli("lut", "--from", "A", "--to", "F2", "--method", method, "--format", fmt,
            "-o", cli_path, *args)
    assert py_path.read_bytes() == cli_path.read_bytes()
    assert result["lut"] == str(py_path)
    assert result["lattice"] == (size is not None or method == "rootpoly")
    if fmt in ("cube", "spi3d"):
        shaper_py = tmp_path / "py" / "lut.shaper.clf"
        assert result["shaper"] == str(shaper_py)
        assert shaper_py.read_bytes() == (tmp_path / "cli" / "lut.shaper.clf").read_bytes()
    else:
        assert result["shaper"] is None


@pytest.mark.parametrize("method, fmt, encoding", [
    ("bradford", "resolve_cube", "acescct"),  # one file, no shaper, for Resolve
    ("band3", "houdini", "acescc"),
    ("rootpoly", "clf", "acescct"),             # non-linear: the lattice alone
])
def test_log_encoded_luts_equal_the_commands(tmp_path, method, fmt, encoding):
    ext = {"resolve_cube": "cube", "houdini": "lut"}.get(fmt, fmt)
    # The same file name in two folders: a .cube names its companion shaper.
    (tmp_path / "py").mkdir()
    (tmp_path / "cli").mkdir()
    py_path, cli_path = tmp_path / "py" / f"lut.{ext}", tmp_path / "cli" / f"lut.{ext}"
    result = bandlight.lut(py_path, "A", "D65", method, format=fmt, size=9, encoding=encoding)
    run_cli("lut", "--from", "A", "--to", "D65", "--method", method, "--format", fmt,
            "--size", 9, "--encoding", encoding, "-o", cli_path)
    assert py_path.read_bytes() == cli_path.read_bytes()
    assert result["encoding"] == encoding
    assert result["shaper"] is None and result["shaper_description"] is None
    assert result["lattice"]
    title = {"acescct": "ACEScct", "acescc": "ACEScc"}[encoding]
    assert result["encoding_description"].startswith(f"Input and output: {title} (Academy S-")
    # The grey 0.18 comes back as the exact transform's grey, in the encoding.
    exact = bandlight.lut(tmp_path / "exact.clf", "A", "D65", method, size=33 if
                          method == "rootpoly" else None)
    assert exact["encoding"] == "linear"
    cpu = OCIO.Config.CreateRaw().getProcessor(
        OCIO.FileTransform(str(py_path), interpolation=OCIO.INTERP_TETRAHEDRAL)).getDefaultCPUProcessor()
    exact_cpu = OCIO.Config.CreateRaw().getProcessor(
        OCIO.FileTransform(str(tmp_path / "exact.clf"))).getDefaultCPUProcessor()
    # Academy S-2016-001 / S-2014-003 above their toes: (log2 x + 9.72) / 17.52.
    grey = (np.log2(0.18) + 9.72) / 17.52
    encoded = np.array(cpu.applyRGB([grey] * 3))
    linear = np.exp2(encoded * 17.52 - 9.72)
    np.testing.assert_allclose(linear, exact_cpu.applyRGB([0.18] * 3), rtol=2e-3)


def test_lut_errors_are_the_commands(tmp_path):
    with pytest.raises(ValueError) as e:
        bandlight.lut(tmp_path / "x.cube", "A", "D65", format="cube", encoding="log")
    assert str(e.value) == "unknown LUT encoding 'log' (linear, acescct, acescc)"
    assert cli_error("lut", "--from", "A", "--to", "D65", "--format", "cube", "--encoding", "log",
                     "-o", tmp_path / "x.cube") == (
        "unknown LUT --encoding 'log' (linear, acescct, acescc)")
    with pytest.raises(ValueError) as e:
        bandlight.lut(tmp_path / "x.png", "A", "D65", format="png")
    assert str(e.value) == cli_error("lut", "--from", "A", "--to", "D65", "--format", "png",
                                     "-o", tmp_path / "y.png")
    # The same message, each face naming its own parameters: the command's
    # --shaper none is Python's shaper=none.
    with pytest.raises(ValueError) as e:
        bandlight.lut(tmp_path / "x.csp", "A", "D65", format="csp", size=9)
    command = cli_error("lut", "--from", "A", "--to", "D65", "--format", "csp",
                        "--size", "9", "-o", tmp_path / "x.csp")
    assert "use --shaper none" in command and "or --format cube" in command
    assert "--encoding acescct" in command
    assert str(e.value) == (command.replace("--shaper ", "shaper=").replace("--format ", "format=")
                            .replace("--encoding ", "encoding="))
    missing = tmp_path / "no" / "such" / "dir" / "x.clf"
    with pytest.raises(FileNotFoundError) as e:
        bandlight.lut(missing, "A", "D65")
    assert str(e.value) == cli_error("lut", "--from", "A", "--to", "D65", "-o", missing)
    assert e.value.errno == 2
