"""lb.run: the records of results.csv as a DataFrame, from a dict or a file."""

import json

import pandas as pd

import lumibench as lb
from conftest import ROOT


def test_run_returns_the_records_of_results_csv(tmp_path):
    # The smoke experiment cut to one scene and a short MCI curve (the whole
    # of it takes minutes: the CLI's tests run it).
    exp = json.loads((ROOT / "experiments" / "smoke.json").read_text())
    exp.update(luminaires=["lambert.ldt"], heights=[1.1], rotations=["3pi/4"], mci_curve=[1, 4, 16], res=16,
               time_res=32, seeds=2)
    out = tmp_path / "out"
    frame = lb.run(exp, out, report=False)
    records = json.loads((out / "results.json").read_text())
    records = records["records"] if isinstance(records, dict) else records
    assert len(frame) == len(records) > 0
    assert frame.equals(pd.read_csv(out / "results.csv"))
    # one record per method of the one scene, its spec canonical (every key written out)
    rows = frame[frame["role"] == "method"]
    assert sorted(rows["method"]) == sorted(m.split(":")[0] for m in exp["methods"])
    assert all(s.startswith(m + ":") for m, s in zip(rows["method"], rows["spec"]))
    assert frame.attrs["summary"]["computed"] == len(records)
    # the dict was kept as the experiment file, and a rerun from it resumes
    again = lb.run(out / "experiment.json", out, report=False)
    assert again.attrs["summary"]["computed"] == 0 and again.attrs["summary"]["skipped"] == len(records)
    assert again.equals(frame)


def test_run_bad_input(tmp_path):
    f = tmp_path / "file"
    f.write_text("x")
    try:
        lb.run({"name": "x"}, f)
    except ValueError as e:
        assert str(e).startswith("out: expected a directory path")
    else:
        raise AssertionError("no error")
    try:
        lb.run({"name": "x", "nosuchkey": 1}, tmp_path / "o")
    except ValueError as e:
        assert "nosuchkey" in str(e)
    else:
        raise AssertionError("no error")
