# SPDX-License-Identifier: BSD-3-Clause
"""Shared fixtures of the Python module's tests.

ctest runs them with /usr/bin/python3 -m pytest, PYTHONPATH=<build>/python
and BANDLIGHT_EXE=<the bandlight command> (tests/CMakeLists.txt); the module
is checked against that command on the same input.
"""

import json
import os
import pathlib
import subprocess

import pytest

import bandlight

SOURCE_DIR = pathlib.Path(os.environ.get("BANDLIGHT_SOURCE_DIR",
                                         pathlib.Path(__file__).resolve().parents[2]))
SPECTRAL_DATA = SOURCE_DIR / "tests" / "spectral" / "data"
ROBUSTNESS_DATA = SOURCE_DIR / "tests" / "robustness" / "data"
SCENES = SOURCE_DIR / "scenes"


def _exe():
    exe = os.environ.get("BANDLIGHT_EXE")
    if not exe or not os.access(exe, os.X_OK):
        pytest.fail("BANDLIGHT_EXE must name the built bandlight command "
                    f"(got {exe!r}); ctest sets it")
    return exe


@pytest.fixture(scope="session")
def exe():
    return _exe()


def run_cli(*args, check=True, cwd=None):
    """Runs the bandlight command; returns the CompletedProcess (text)."""
    p = subprocess.run([_exe(), *map(str, args)], capture_output=True, text=True, cwd=cwd)
    if check and p.returncode != 0:
        pytest.fail(f"bandlight {' '.join(map(str, args))} failed ({p.returncode}):\n"
                    f"{p.stdout}\n{p.stderr}")
    return p


def acescg_spec(width, height, channels):
    """A float ImageSpec that says its pixels are linear ACEScg (the Color
    Interop Forum's ID, as bandlight writes it): plates as a pipeline tags
    them, so `apply` converts nothing and notes nothing."""
    import OpenImageIO as oiio
    spec = oiio.ImageSpec(width, height, channels, "float")
    spec.attribute("colorInteropID", "lin_ap1_scene")
    return spec


def cli_json(*args):
    return json.loads(run_cli(*args).stdout)


def cli_error(*args):
    """The one-line error of a failing command, without its "bandlight: " prefix."""
    p = run_cli(*args, check=False)
    assert p.returncode == 2, (p.returncode, p.stdout, p.stderr)
    line = p.stderr.strip().splitlines()[-1]
    assert line.startswith("bandlight: "), line
    return line[len("bandlight: "):]


@pytest.fixture(autouse=True)
def _notes_are_visible():
    # A NoteWarning nobody expects is a test failure, not noise.
    import warnings
    with warnings.catch_warnings():
        warnings.simplefilter("error", bandlight.NoteWarning)
        yield
