# SPDX-License-Identifier: BSD-3-Clause
"""bandlight on a Dask cluster of processes (Debian's python3-distributed,
over loopback): a pickled Relighter relights a dask array, and apply()
spreads a frame sequence over the workers, with the local call's pixels."""

import numpy as np
import OpenImageIO as oiio
import pytest

import bandlight
from conftest import acescg_spec

distributed = pytest.importorskip("distributed")
da = pytest.importorskip("dask.array")


@pytest.fixture(scope="module")
def client():
    cluster = distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=True,
                                       host="127.0.0.1", dashboard_address=None)
    with distributed.Client(cluster) as c:
        yield c
    cluster.close()


def test_a_dask_array_relit_on_two_worker_processes(client):
    rng = np.random.default_rng(5)
    image = rng.uniform(0.0, 8.0, (256, 192, 3)).astype(np.float32)
    r = bandlight.Relighter("A", "D65", "rootpoly", plates="lit")
    lazy = da.from_array(image, chunks=(64, 192, 3)).map_blocks(r.apply, dtype=np.float32)
    np.testing.assert_array_equal(lazy.compute(scheduler=client), r.apply(image))
    assert len(client.scheduler_info()["workers"]) == 2


def test_a_frame_sequence_spread_over_the_workers(client, tmp_path):
    for f in range(1, 9):
        px = np.full((8, 16, 3), 0.05 * f, np.float32)
        out = oiio.ImageOutput.create(str(tmp_path / f"p.{f:04d}.exr"))
        assert out.open(str(tmp_path / f"p.{f:04d}.exr"), acescg_spec(16, 8, 3))
        assert out.write_image(px)
        out.close()
    spread = bandlight.apply(tmp_path / "p.####.exr", tmp_path / "d.####.exr", frames="1-8",
                             src="F11", dst="D65", client=client)
    assert spread["frames"] == 8 and spread["failed"] == []
    local = bandlight.apply(tmp_path / "p.####.exr", tmp_path / "l.####.exr", frames="1-8",
                            src="F11", dst="D65")
    assert local["applied"] == spread["applied"]
    for f in range(1, 9):
        a = oiio.ImageInput.open(str(tmp_path / f"d.{f:04d}.exr")).read_image("float")
        b = oiio.ImageInput.open(str(tmp_path / f"l.{f:04d}.exr")).read_image("float")
        np.testing.assert_array_equal(a, b)
    again = bandlight.apply(tmp_path / "p.####.exr", tmp_path / "d.####.exr", frames="1-8",
                            src="F11", dst="D65", client=client, skip_existing=True)
    assert again["skipped"] == 8 and again["frames"] == 0


def test_a_frame_missing_on_a_worker_raises_as_it_would_here(client, tmp_path):
    # The worker's FileNotFoundError is pickled back with its class, message,
    # errno and filename: the local call's exception.
    missing = tmp_path / "p.0002.exr"
    with pytest.raises(FileNotFoundError) as remote:
        bandlight.apply(tmp_path / "p.####.exr", tmp_path / "d.####.exr", frames="2",
                        src="F11", dst="D65", client=client)
    with pytest.raises(FileNotFoundError) as local:
        bandlight.apply(tmp_path / "p.####.exr", tmp_path / "d.####.exr", frames="2",
                        src="F11", dst="D65")
    assert type(remote.value) is type(local.value)
    assert str(remote.value) == str(local.value)
    assert remote.value.filename == local.value.filename == str(missing)
    assert remote.value.errno == local.value.errno


def test_lights_scored_on_the_workers_as_here(client):
    # quality() is a plain function of picklable arguments returning
    # picklable records: client.map spreads lights over the workers.
    lights = ["F1", "F2", "F7", "F11", "planck:3200", "daylight:5600"]
    remote = client.gather(client.map(bandlight.quality, lights, reference="D65"))
    assert remote == bandlight.quality(lights, reference="D65")
