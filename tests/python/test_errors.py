# SPDX-License-Identifier: BSD-3-Clause
"""Errors are ValueError / the OSError subclass of their errno, with the
command's one-line message."""

import errno
import os
import pathlib
import pickle
import warnings

import numpy as np
import pytest

import bandlight
from conftest import ROBUSTNESS_DATA, acescg_spec, cli_error

MALFORMED = ROBUSTNESS_DATA / "malformed"


def test_bad_method_is_a_value_error_with_the_commands_message(tmp_path):
    with pytest.raises(ValueError) as e:
        bandlight.illuminant_change("A", "D65", method="bogus")
    assert str(e.value) == cli_error("lut", "--from", "A", "--to", "D65", "--method", "bogus",
                                     "-o", tmp_path / "x.clf")
    assert str(e.value).startswith("unknown method 'bogus' (none, vonkries, bradford")
    for call in (lambda: bandlight.Relighter("A", "D65", "bogus"),
                 lambda: bandlight.relight([[0.1, 0.2, 0.3]], "A", "D65", "bogus"),
                 lambda: bandlight.method_name("bogus"),
                 lambda: bandlight.illuminant_change_matrix("A", "D65", "bogus")):
        with pytest.raises(ValueError) as again:
            call()
        assert str(again.value) == str(e.value)


def test_bad_names_are_value_errors_with_the_commands_message():
    with pytest.raises(ValueError) as e:
        bandlight.xyz("Q42")
    assert str(e.value) == cli_error("xyz", "--illuminant", "Q42")
    with pytest.raises(ValueError) as e:
        bandlight.xyz("A", "TCS99")
    assert str(e.value) == cli_error("xyz", "--illuminant", "A", "--reflectance", "TCS99")
    with pytest.raises(ValueError) as e:
        bandlight.xyz("A", observer="1950")
    assert str(e.value) == cli_error("xyz", "--illuminant", "A", "--observer", "1950")
    with pytest.raises(ValueError) as e:
        bandlight.illuminant_change("A", "D65", working_space="adobe")
    assert str(e.value) == cli_error("lut", "--from", "A", "--to", "D65", "--working-space",
                                     "adobe", "-o", "/tmp/never-written.clf")
    with pytest.raises(ValueError) as e:
        bandlight.tables("400,x")
    assert str(e.value) == cli_error("tables", "--bands", "400,x")


@pytest.mark.parametrize("name", sorted(p.name for p in MALFORMED.glob("*")
                                        if p.suffix in (".csv", ".sp")))
def test_malformed_spectrum_files_name_file_and_line(name):
    path = MALFORMED / name
    if name == "bom_crlf.csv":
        assert bandlight.read_spectra(path)  # UTF-8 with BOM and CRLF is fine
        return
    with pytest.raises(ValueError) as e:
        bandlight.read_spectra(path)
    assert not isinstance(e.value, OSError)
    assert str(e.value) == cli_error("xyz", "--illuminant", path)
    assert str(e.value).startswith(f"{path}:")


def test_malformed_csv_names_the_line():
    with pytest.raises(ValueError, match=r"^mine\.csv:4: expected a number for a spectral "
                                         r"value, got 'abc'$"):
        bandlight.parse_spectra("nm,a\n380,0.1\n385,0.2\n390,abc\n", "mine.csv")


def test_missing_and_unreadable_files_are_os_errors(tmp_path):
    missing = tmp_path / "missing.csv"
    with pytest.raises(FileNotFoundError) as e:
        bandlight.read_spectra(missing)
    assert e.value.errno == errno.ENOENT
    assert str(e.value) == f"{missing}: cannot open spectrum file"
    # A path is a file: the command's message for it.
    with pytest.raises(FileNotFoundError) as e:
        bandlight.illuminant(missing)
    with pytest.raises(FileNotFoundError) as e:
        bandlight.reflectances(missing)
    with pytest.raises(IsADirectoryError) as e:
        bandlight.read_spectra(tmp_path)
    assert e.value.errno == errno.EISDIR
    assert e.value.filename == str(tmp_path)
    assert str(e.value) == f"{tmp_path}: is a directory, not a spectrum file"
    assert str(e.value) == cli_error("xyz", "--illuminant", "A", "--reflectance", tmp_path)
    # As --illuminant reads a str: a name with a folder or an extension is a
    # file that is not there, as the command says; a bare unknown name (it
    # may be a typo) is a ValueError listing the built-in names.
    with pytest.raises(FileNotFoundError) as e:
        bandlight.illuminant(str(missing))
    assert str(e.value) == cli_error("xyz", "--illuminant", missing)
    with pytest.raises(ValueError, match="unknown illuminant 'D66x'"):
        bandlight.illuminant("D66x")


def test_os_errors_keep_the_message_alone(tmp_path):
    with pytest.raises(FileNotFoundError) as e:
        bandlight.render(tmp_path / "none.yaml")
    assert e.value.errno == errno.ENOENT
    assert str(e.value) == f"{tmp_path / 'none.yaml'}: cannot open scene file"
    assert str(e.value) == cli_error("render", tmp_path / "none.yaml")
    assert e.value.filename == str(tmp_path / "none.yaml")
    assert e.value.strerror == str(e.value)
    # Raised in a worker (dask, multiprocessing), it arrives as it was.
    again = pickle.loads(pickle.dumps(e.value))
    assert type(again) is type(e.value)
    assert (str(again), again.errno, again.filename) == (str(e.value), errno.ENOENT,
                                                         str(tmp_path / "none.yaml"))


def write_plate(path):
    import OpenImageIO as oiio
    out = oiio.ImageOutput.create(str(path))
    assert out.open(str(path), acescg_spec(4, 2, 3))
    assert out.write_image(np.full((2, 4, 3), 0.25, dtype=np.float32))
    out.close()


def write_spectral_image(path):
    """A 2 x 2 emissive spectral EXR (Fichet 2021 channel names, 5 nm)."""
    import OpenImageIO as oiio
    grid = range(380, 781, 5)
    spec = oiio.ImageSpec(2, 2, len(grid), "float")
    spec.channelnames = tuple(f"S0.{nm},000000nm" for nm in grid)
    spec.attribute("spectralLayoutVersion", "1.0")
    spec.attribute("emissiveUnits", "W.m^-2.sr^-1")
    out = oiio.ImageOutput.create(str(path))
    assert out.open(str(path), spec)
    assert out.write_image(np.full((2, 2, len(grid)), 0.5, dtype=np.float32))
    out.close()


def unwritable_folder(tmp_path):
    """A folder where creating a file fails with EACCES, or None: one without
    write permission, or for root (whom permissions do not stop) sysfs,
    which refuses new files with EACCES."""
    if os.geteuid() != 0:
        locked = tmp_path / "locked"
        locked.mkdir()
        locked.chmod(0o555)
        return locked
    try:
        open("/sys/bandlight-probe", "w").close()
    except PermissionError:
        return pathlib.Path("/sys")
    except OSError:
        return None
    os.remove("/sys/bandlight-probe")
    return None


def test_a_missing_image_is_file_not_found(tmp_path):
    missing, out = tmp_path / "missing.exr", tmp_path / "o.exr"
    with pytest.raises(FileNotFoundError) as e:
        bandlight.apply(missing, out, src="A", dst="D65")
    assert e.value.errno == errno.ENOENT
    assert e.value.filename == str(missing)
    assert str(e.value) == cli_error("apply", missing, out, "--from", "A", "--to", "D65")
    assert str(e.value).startswith(f"{missing}: cannot read image: ")
    with pytest.raises(FileNotFoundError):
        bandlight.read_spectral_image(missing)
    with pytest.raises(FileNotFoundError) as e:
        bandlight.spectral(missing, out)
    assert str(e.value) == cli_error("spectral", missing, out)
    assert not out.exists()
    # The command's own case: a relative name in the working folder.
    os.chdir(tmp_path)
    with pytest.raises(FileNotFoundError) as e:
        bandlight.apply("missing.exr", "o.exr", src="A", dst="D65")
    assert e.value.filename == "missing.exr"
    with pytest.raises(FileNotFoundError) as e:
        bandlight.apply("", "o.exr", src="A", dst="D65")
    assert str(e.value).startswith("'' (an empty path): cannot read image")
    assert str(e.value) == cli_error("apply", "", "o.exr", "--from", "A", "--to", "D65")


def test_writing_into_a_missing_folder_is_file_not_found(tmp_path):
    write_plate(tmp_path / "plate.exr")
    out = tmp_path / "none" / "o.exr"
    with pytest.raises(FileNotFoundError) as e:
        bandlight.apply(tmp_path / "plate.exr", out, src="A", dst="D65")
    assert e.value.errno == errno.ENOENT
    assert e.value.filename == str(out)
    assert str(e.value) == cli_error("apply", tmp_path / "plate.exr", out, "--from", "A",
                                     "--to", "D65")
    lut = tmp_path / "none" / "x.clf"
    with pytest.raises(FileNotFoundError) as e:
        bandlight.lut(lut, "A", "D65")
    assert e.value.filename == str(lut)
    assert str(e.value) == cli_error("lut", "--from", "A", "--to", "D65", "-o", lut)
    # Under a file: NotADirectoryError; over a folder: IsADirectoryError.
    (tmp_path / "file").write_text("")
    with pytest.raises(NotADirectoryError) as e:
        bandlight.lut(tmp_path / "file" / "x.clf", "A", "D65")
    assert e.value.errno == errno.ENOTDIR
    (tmp_path / "folder.clf").mkdir()
    with pytest.raises(IsADirectoryError) as e:
        bandlight.lut(tmp_path / "folder.clf", "A", "D65")
    assert e.value.errno == errno.EISDIR
    assert e.value.filename == str(tmp_path / "folder.clf")
    # The message names the parameter as each face spells it.
    assert str(e.value) == f"out '{tmp_path / 'folder.clf'}' is a folder, not a file"
    assert cli_error("lut", "--from", "A", "--to", "D65", "-o", tmp_path / "folder.clf") == \
        f"--out '{tmp_path / 'folder.clf'}' is a folder, not a file"
    # An empty output name is a bad value, refused by name before anything is written.
    with pytest.raises(ValueError, match=r"^out is '' \(an empty path\)") as e:
        bandlight.lut("", "A", "D65")
    assert not isinstance(e.value, OSError)


def test_writing_where_files_cannot_be_created_is_a_permission_error(tmp_path):
    folder = unwritable_folder(tmp_path)
    if folder is None:
        pytest.skip("running as root where sysfs is absent or creates files: no folder here "
                    "refuses a new file with EACCES")
    write_plate(tmp_path / "plate.exr")
    for out, call, args in [
            (folder / "bandlight-o.exr",
             lambda o: bandlight.apply(tmp_path / "plate.exr", o, src="A", dst="D65"),
             ("apply", tmp_path / "plate.exr", "{out}", "--from", "A", "--to", "D65")),
            (folder / "bandlight-x.clf", lambda o: bandlight.lut(o, "A", "D65"),
             ("lut", "--from", "A", "--to", "D65", "-o", "{out}"))]:
        with pytest.raises(PermissionError) as e:
            call(out)
        assert e.value.errno == errno.EACCES
        assert e.value.filename == str(out)
        assert str(e.value).startswith(f"{out}: cannot ")
        assert str(e.value) == cli_error(*[out if a == "{out}" else a for a in args])
        assert not out.exists()


def test_malformed_images_and_configs_are_value_errors(tmp_path):
    (tmp_path / "text.exr").write_text("not an image\n")
    with pytest.raises(ValueError) as e:
        bandlight.apply(tmp_path / "text.exr", tmp_path / "o.exr", src="A", dst="D65")
    assert not isinstance(e.value, OSError)
    assert str(e.value) == cli_error("apply", tmp_path / "text.exr", tmp_path / "o.exr",
                                     "--from", "A", "--to", "D65")
    (tmp_path / "bad.ocio").write_text("ocio_profile_version: 2\nroles: [\n")
    with pytest.raises(ValueError) as e:
        bandlight.config(base=tmp_path / "bad.ocio")
    assert not isinstance(e.value, OSError)
    assert str(e.value).startswith(f"{tmp_path / 'bad.ocio'}:")


def test_a_nul_byte_in_a_path_is_a_value_error_and_writes_nothing(tmp_path):
    write_spectral_image(tmp_path / "shot.exr")
    write_plate(tmp_path / "plate.exr")
    before = sorted(tmp_path.iterdir())
    # The system would read the name only up to the NUL: "nul.exr".
    with pytest.raises(ValueError) as e:
        bandlight.spectral(tmp_path / "shot.exr", f"{tmp_path}/nul.exr\0.png")
    assert not isinstance(e.value, OSError)
    assert "NUL byte" in str(e.value)
    with pytest.raises(ValueError):
        bandlight.apply(tmp_path / "plate.exr", f"{tmp_path}/nul.exr\0.png", src="A", dst="D65")
    with pytest.raises(ValueError):
        bandlight.apply(f"{tmp_path}/plate.exr\0.png", tmp_path / "o.exr", src="A", dst="D65")
    with pytest.raises(ValueError):
        bandlight.lut(f"{tmp_path}/nul.clf\0.cube", "A", "D65")
    (tmp_path / "lamp.csv").write_text("nm,lamp\n380,1\n780,1\n")
    for call in (lambda: bandlight.read_spectra(f"{tmp_path}/lamp.csv\0x"),
                 lambda: bandlight.illuminant(f"{tmp_path}/lamp.csv\0x"),
                 lambda: bandlight.reflectances(f"{tmp_path}/lamp.csv\0x")):
        with pytest.raises(ValueError):
            call()
    assert sorted(tmp_path.iterdir()) == sorted(before + [tmp_path / "lamp.csv"])


def test_notes_are_warnings_and_can_be_errors():
    short = ROBUSTNESS_DATA / "grey_400_700.csv"
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        bandlight.reflectances(short)
    notes = [w for w in caught if issubclass(w.category, bandlight.NoteWarning)]
    assert len(notes) == 1
    assert issubclass(bandlight.NoteWarning, UserWarning)
    with pytest.raises(bandlight.NoteWarning):
        bandlight.reflectances(short)  # conftest turns notes into errors


def test_type_errors_for_wrong_kinds():
    with pytest.raises(TypeError):
        bandlight.illuminant_change(42, "D65")
    with pytest.raises(TypeError):
        bandlight.reflectances(42)
    with pytest.raises(TypeError, match="bandlight.Spectrum, not int"):
        bandlight.remittance_bands([1, 2])
    with pytest.raises(TypeError, match="PyOpenColorIO.Config, not int"):
        bandlight.identify_scene_linear(42)
    with pytest.raises(TypeError, match="one number per band"):
        bandlight.material_tint("abc")
    with pytest.raises(TypeError, match="edges in nm"):
        bandlight.illuminant_bands("A", ["400", "500", "600", "700"])
