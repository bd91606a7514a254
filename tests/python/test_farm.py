# SPDX-License-Identifier: BSD-3-Clause
"""docs/renderfarm/: each farm template's command, expanded for one chunk as the
farm would expand it, runs and writes that chunk's frames."""

import importlib.util
import os
import shlex
import subprocess

import numpy as np
import OpenImageIO as oiio

from conftest import acescg_spec, SOURCE_DIR, _exe, run_cli

FARM = SOURCE_DIR / "docs" / "renderfarm"


def make_show(tmp_path):
    """Plates 1001-1012 and the package config, where the templates' paths point."""
    plates = tmp_path / "plates"
    plates.mkdir()
    for f in range(1001, 1013):
        px = np.full((8, 16, 4), 0.18, np.float32)
        px[..., 0] = 0.01 * (f - 1000)
        out = oiio.ImageOutput.create(str(plates / f"A001.{f}.exr"))
        assert out.open(str(plates / f"A001.{f}.exr"), acescg_spec(16, 8, 4))
        assert out.write_image(px)
        out.close()
    run_cli("package", "--out", tmp_path / "ocio" / "bandlight-package")
    (tmp_path / "relit").mkdir()
    return tmp_path


def localise(args, show):
    """The template's show paths under this test's folder."""
    return [a.replace("/show/", f"{show}/") for a in args]


def written(show):
    return sorted(p.name for p in (show / "relit").iterdir())


def test_opencue_shell_layer_chunk(tmp_path):
    show = make_show(tmp_path)
    spec = importlib.util.spec_from_file_location("opencue_job", FARM / "opencue_job.py")
    job = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(job)
    cmd = job.command("/show/plates/A001.####.exr", "/show/relit/A001.####.exr")
    # What OpenCue does for the chunk 1001-1010 of a 10-frame chunked layer.
    cmd = [a.replace("#FRAME_START#", "1001").replace("#FRAME_END#", "1010") for a in cmd]
    cmd = localise(cmd, show)
    cmd[0] = _exe()
    p = subprocess.run(cmd, capture_output=True, text=True)
    assert p.returncode == 0, p.stderr
    assert written(show) == [f"A001.{f}.exr" for f in range(1001, 1011)]


def test_deadline_command_line_job_task(tmp_path):
    show = make_show(tmp_path)
    fields = {}
    for line in (FARM / "deadline_job.txt").read_text().splitlines():
        if line.startswith("-"):
            key, _, value = line.partition(" ")
            fields[key] = value.strip()
    assert fields["-chunksize"] == "10"
    args = shlex.split(fields["-arguments"].strip('"'))
    args = [a.replace("<STARTFRAME>", "1011").replace("<ENDFRAME>", "1012") for a in args]
    p = subprocess.run([_exe(), *localise(args, show)], capture_output=True, text=True)
    assert p.returncode == 0, p.stderr
    assert written(show) == ["A001.1011.exr", "A001.1012.exr"]


def test_slurm_array_task(tmp_path):
    show = make_show(tmp_path)
    env = dict(os.environ, SLURM_ARRAY_TASK_ID="1", CHUNK="4", SLURM_CPUS_PER_TASK="1",
               BANDLIGHT=_exe(), INPUT=f"{show}/plates/A001.####.exr",
               OUTPUT=f"{show}/relit/A001.####.exr",
               CONFIG=f"{show}/ocio/bandlight-package")
    p = subprocess.run(["bash", str(FARM / "slurm_array.sh")], env=env, capture_output=True,
                       text=True)
    assert p.returncode == 0, p.stderr
    # Task 1 of chunks of 4 from 1001: frames 1005-1008.
    assert written(show) == [f"A001.{f}.exr" for f in range(1005, 1009)]
    # The same task re-queued skips what it wrote.
    p = subprocess.run(["bash", str(FARM / "slurm_array.sh")], env=env, capture_output=True,
                       text=True)
    assert p.returncode == 0 and "to 0 frames (4 skipped, 0 failed)" in p.stdout
