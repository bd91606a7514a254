# SPDX-License-Identifier: BSD-3-Clause
"""Errors are ValueError / OSError with the command's one-line message."""

import errno
import warnings

import pytest

import bandlight
from conftest import ROBUSTNESS_DATA, cli_error

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
    assert str(e.value) == cli_error("xyz", "--illuminant", "A", "--reflectance", tmp_path)
    # As --illuminant reads a str: an unknown name (it may be a typo) is a
    # ValueError listing the built-in names, as the command says.
    with pytest.raises(ValueError) as e:
        bandlight.illuminant(str(missing))
    assert str(e.value) == cli_error("xyz", "--illuminant", missing)


def test_os_errors_keep_the_message_alone(tmp_path):
    with pytest.raises(OSError) as e:
        bandlight.render(tmp_path / "none.yaml")
    assert e.value.errno == errno.ENOENT
    assert str(e.value) == f"{tmp_path / 'none.yaml'}: cannot open scene file"
    assert e.value.filename is None


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
