# SPDX-License-Identifier: BSD-3-Clause
"""`cmake --install` puts an importable package under the prefix."""

import os
import pathlib
import re
import subprocess
import sys

import pytest


def build_dir():
    build = os.environ.get("BANDLIGHT_BUILD_DIR")
    if not build or not (pathlib.Path(build) / "CMakeCache.txt").is_file():
        pytest.fail(f"BANDLIGHT_BUILD_DIR must name the build tree (got {build!r}); ctest sets it")
    return pathlib.Path(build)


def test_install_gives_an_importable_package(tmp_path):
    build = build_dir()
    cache = (build / "CMakeCache.txt").read_text()
    site_rel = re.search(r"^BANDLIGHT_PYTHON_INSTALL_DIR:STRING=(.*)$", cache, re.M).group(1)
    assert site_rel == f"lib/python{sys.version_info.major}.{sys.version_info.minor}/dist-packages"
    prefix = tmp_path / "prefix"
    cmake = os.environ.get("CMAKE_COMMAND", "cmake")
    p = subprocess.run([cmake, "--install", str(build), "--prefix", str(prefix)],
                       capture_output=True, text=True)
    assert p.returncode == 0, p.stdout + p.stderr
    package = prefix / site_rel / "bandlight"
    assert (package / "__init__.py").is_file()
    assert (package / "__init__.pyi").is_file()
    assert (package / "py.typed").is_file()
    assert list(package.glob("_bandlight*.so"))
    code = ("import bandlight, PyOpenColorIO as OCIO\n"
            "assert type(bandlight.illuminant_change('A', 'D65')) is OCIO.GroupTransform\n"
            "print(bandlight.__file__)\n")
    env = {k: v for k, v in os.environ.items() if k != "PYTHONPATH"}
    env["PYTHONPATH"] = str(prefix / site_rel)
    p = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, env=env,
                       cwd=tmp_path)
    assert p.returncode == 0, p.stderr
    assert p.stdout.strip() == str(package / "__init__.py")
