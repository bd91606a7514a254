# SPDX-License-Identifier: BSD-3-Clause
"""The Python example of docs/python.md runs as printed."""

import re
import subprocess
import sys

import numpy as np
import OpenImageIO as oiio

from conftest import acescg_spec, SOURCE_DIR


def readme_example():
    text = (SOURCE_DIR / "docs" / "python.md").read_text()
    blocks = re.findall(r"```python\n(.*?)```", text, re.S)
    # The example, then the Dask one (which needs a cluster: test_dask.py
    # runs what it shows).
    assert len(blocks) == 2 and "client=client" in blocks[1]
    return blocks[0]


def test_readme_example_runs(tmp_path):
    # A small tungsten plate with alpha, where the example expects one.
    rng = np.random.default_rng(7)
    plate = rng.uniform(0.0, 2.0, (32, 48, 4)).astype(np.float32)
    plate[..., 3] = 1.0
    out = oiio.ImageOutput.create(str(tmp_path / "plate.exr"))
    assert out.open(str(tmp_path / "plate.exr"), acescg_spec(48, 32, 4))
    assert out.write_image(plate)
    out.close()
    code = readme_example() + (
        "\nassert bradford.shape == plate.shape == (32, 48, 4)"
        "\nassert (bradford[..., 3] == 1).all()"
        "\nassert de.shape == (32, 48) and 0 < de.mean() < 20"
        "\nassert isinstance(t, OCIO.GroupTransform) and isinstance(config, OCIO.Config)"
        "\nassert processor.getDefaultCPUProcessor() is not None\n")
    p = subprocess.run([sys.executable, "-c", code], cwd=tmp_path, capture_output=True,
                       text=True)
    assert p.returncode == 0, p.stderr
    assert re.match(r"mean \d+\.\d\d, 95th percentile \d+\.\d\d dE00", p.stdout), p.stdout
    assert (tmp_path / "my-looks" / "config.ocio").is_file()
    assert not (tmp_path / "bandlight-package").exists()
