# SPDX-License-Identifier: BSD-3-Clause
"""The accuracy report against `bandlight accuracy --json`."""

import json

import pytest

import bandlight
from conftest import SCENES, run_cli

NUMBERS = ("mean", "p95", "max")


def key(row):
    """What identifies a row: every field but the measured ones."""
    return tuple(sorted((k, v) for k, v in row.items() if k not in NUMBERS + ("worst_sample",)))


def cli_rows(*args):
    j = json.loads(run_cli("accuracy", *args, "--no-cost", "--json", "-").stdout)
    return j


def assert_same_rows(py_rows, by_cli):
    assert py_rows, "no rows"
    assert set(py_rows[0]) == set(by_cli[0]), "the rows' fields differ from the command's"
    index = {key(r): r for r in by_cli}
    for r in py_rows:
        c = index.get(key(r))
        assert c is not None, f"the command has no row {key(r)}"
        for n in NUMBERS:
            assert r[n] == pytest.approx(c[n], rel=1e-9, abs=1e-12), (key(r), n)
        assert r["worst_sample"] == c["worst_sample"]


def test_accuracy_rows_equal_the_commands():
    py_rows = bandlight.accuracy(["A", "F11"], ["bradford", "band3", "metamer"], ideal_only=True)
    by_cli = cli_rows("--illuminants", "A,F11", "--methods", "bradford,band3,metamer",
                      "--ideal-only")
    rows = by_cli["rows"]
    assert_same_rows(py_rows, rows)
    # The command adds its spectral reference; otherwise the same rows.
    assert len(py_rows) == len([r for r in rows if r["method"] != "spectral"])
    assert {r["set"] for r in py_rows} == {"tcs", "tcs09-15", "random"}
    # Every linear method is exposure invariant: the same figure at every k.
    by_k = {}
    for r in py_rows:
        by_k.setdefault(key({**r, "exposure": 0}), set()).add(round(r["mean"], 9))
    assert all(len(v) == 1 for v in by_k.values())
    # band3 is worse than bradford on average (README's table).
    mean = lambda m: sum(r["mean"] for r in py_rows if r["method"] == m) / 2  # noqa: E731
    assert mean("band3") > mean("bradford")


def test_shipped_forms_cross_validation_and_floor(tmp_path):
    extra = tmp_path / "mine.csv"
    extra.write_text((SCENES / "counterexample_surface.csv").read_text())
    kwargs = dict(illuminants="A,D65", methods=["bradford", "fit3x3"], lut_size=9,
                  reflectances=[extra], exposures=[0.25, 1.0], cross_validation=True,
                  floor=True)
    calls = []
    py_rows = bandlight.accuracy(**kwargs, progress=calls.append)
    assert calls and calls[-1] == pytest.approx(1.0)
    assert {r["shipped"] for r in py_rows} == {False, True}
    assert str(extra) in {r["set"] for r in py_rows}
    by_cli = cli_rows("--illuminants", "A,D65", "--methods", "bradford,fit3x3",
                      "--lut-size", "9", "--reflectances", extra)
    measured = [r for r in py_rows if r["exposure"] in (0.25, 1.0)
                and not r["set"].startswith("training") and not r["method"].startswith("floor")]
    assert_same_rows(measured, by_cli["rows"])
    assert_same_rows([r for r in py_rows if r["set"].startswith("training")],
                     by_cli["cross_validation"])
    assert_same_rows([r for r in py_rows if r["method"].startswith("floor")], by_cli["floor"])


def test_accuracy_errors_and_progress_exceptions():
    with pytest.raises(ValueError, match="at least two illuminants"):
        bandlight.accuracy(["A"])
    with pytest.raises(ValueError, match="unknown method 'nope'"):
        bandlight.accuracy(["A", "D65"], ["nope"])

    def stop(fraction):
        raise KeyboardInterrupt("stop")

    with pytest.raises(KeyboardInterrupt, match="stop"):
        bandlight.accuracy(["A", "D65"], ["none"], ideal_only=True, default_sets=False,
                           reflectances={"few": bandlight.reflectances("TCS")[:3]},
                           progress=stop)
