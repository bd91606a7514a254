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
    doc = bandlight.accuracy(["A", "F11"], ["bradford", "band3", "metamer"], ideal_only=True,
                             cost=False)
    by_cli = cli_rows("--illuminants", "A,F11", "--methods", "bradford,band3,metamer",
                      "--ideal-only")
    assert list(doc) == list(by_cli) == ["camera", "rows", "cross_validation", "floor", "cost",
                                         "setup_cost"]
    py_rows, rows = doc["rows"], by_cli["rows"]
    assert_same_rows(py_rows, rows)
    # The same rows, the spectral reference's included.
    assert len(py_rows) == len(rows)
    assert "spectral" in {r["method"] for r in py_rows}
    assert_same_rows(doc["floor"], by_cli["floor"])
    assert doc["camera"] is None and doc["cost"] == [] and doc["setup_cost"] == []
    assert {r["set"] for r in py_rows} == {"tcs", "tcs09-15", "random"}
    # Every linear method is exposure invariant: the same figure at every k.
    by_k = {}
    for r in py_rows:
        by_k.setdefault(key({**r, "exposure": 0}), set()).add(round(r["mean"], 9))
    assert all(len(v) == 1 for v in by_k.values())
    # band3 is worse than bradford on average (docs/accuracy.md's table).
    mean = lambda m: sum(r["mean"] for r in py_rows if r["method"] == m) / 2  # noqa: E731
    assert mean("band3") > mean("bradford")


def test_accuracy_document_equals_the_commands_with_costs(tmp_path):
    # The call the two faces share, costs included: the same rows to 1e-9,
    # and a cost row for every method, form and thread count the command times.
    doc = bandlight.accuracy(illuminants=["A", "D65"], methods=["bradford", "rootpoly"])
    out = tmp_path / "accuracy.json"
    run_cli("accuracy", "--illuminants", "A,D65", "--methods", "bradford,rootpoly",
            "--json", out)
    by_cli = json.loads(out.read_text())
    for part in ("rows", "cross_validation", "floor"):
        assert len(doc[part]) == len(by_cli[part]), part
        assert_same_rows(doc[part], by_cli[part])
    timed = lambda d: sorted((c["method"], c["form"], c["threads"]) for c in d["cost"])  # noqa
    assert timed(doc) == timed(by_cli) and len(timed(doc)) >= 6
    assert [s["what"] for s in doc["setup_cost"]] == [s["what"] for s in by_cli["setup_cost"]]
    assert all(c["ns_per_pixel"] > 0 for c in doc["cost"])


def test_shipped_forms_cross_validation_and_floor(tmp_path):
    extra = tmp_path / "mine.csv"
    extra.write_text((SCENES / "counterexample_surface.csv").read_text())
    kwargs = dict(illuminants="A,D65", methods=["bradford", "fit3x3"], lut_size=9,
                  reflectances=[extra], exposures=[0.25, 1.0], cost=False)
    calls = []
    doc = bandlight.accuracy(**kwargs, progress=calls.append)
    py_rows = doc["rows"]
    assert calls and calls[-1] == pytest.approx(1.0)
    assert {r["shipped"] for r in py_rows} == {False, True}
    assert str(extra) in {r["set"] for r in py_rows}
    by_cli = cli_rows("--illuminants", "A,D65", "--methods", "bradford,fit3x3",
                      "--lut-size", "9", "--reflectances", extra)
    measured = [r for r in py_rows if r["exposure"] in (0.25, 1.0)]
    assert_same_rows(measured, by_cli["rows"])
    assert_same_rows(doc["cross_validation"], by_cli["cross_validation"])
    assert_same_rows(doc["floor"], by_cli["floor"])
    # The document and the plot are written as the command writes them.
    bandlight.accuracy(**{**kwargs, "cost": True}, ideal_only=True, cross_validation=False,
                       floor=False, json=tmp_path / "a.json", plot=tmp_path / "a.svg")
    assert json.loads((tmp_path / "a.json").read_text())["rows"]
    assert (tmp_path / "a.svg").read_text().lstrip().startswith("<?xml")


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
                           cost=False, progress=stop)
