"""lb.compare on arrays against `lumibench compare --json` on the files."""

import math

import numpy as np

import lumibench as lb
from conftest import LUM

KEYS = ["nmse", "nrmse", "relmse", "ueb", "leb", "nonfinite", "pixels", "mean_ref", "mean_test", "grad_nmse",
        "grad_pairs", "flip", "width", "height"]


def same(a, b):
    return (a is None and b is None) or a == b or (isinstance(a, float) and math.isnan(a) and b is None)


def test_compare_arrays_equals_compare_files(cli, cli_json, tmp_path):
    ref, test = tmp_path / "ref.exr", tmp_path / "test.exr"
    common = ["--luminaire", LUM, "--height", 0.5, "--rotation", "3pi/4", "--res", 20, "--reps", 1]
    cli("render", *common, "--method", "reference:tol=1e-3", "--out", ref)
    cli("render", *common, "--method", "mc:n=4", "--out", test)
    want = cli_json("compare", ref, test, "--json")
    got = lb.compare(lb.read_exr(str(ref)), lb.read_exr(str(test)))
    for k in KEYS:
        assert same(got[k], want[k]), (k, got[k], want[k])
    assert want["nmse"] > 0 and want["grad_nmse"] > 0  # a real difference, not 0 == 0
    # float64 arrays of the same values give the same metrics (the library computes in double).
    again = lb.compare(lb.read_exr(str(ref)).astype(np.float64), lb.read_exr(str(test)).astype(np.float64),
                       flip=False)
    assert again["nmse"] == want["nmse"] and again["flip"] is None
    # a strided view is read as the array it shows
    big = np.zeros((40, 40), np.float32)
    big[::2, ::2] = lb.read_exr(str(test))
    assert lb.compare(lb.read_exr(str(ref)), big[::2, ::2], flip=False)["nmse"] == want["nmse"]


def test_write_then_read_exr(tmp_path):
    a = np.random.default_rng(1).random((7, 5)).astype(np.float32)
    path = str(tmp_path / "a.exr")
    lb.write_exr(path, a)
    b = lb.read_exr(path)
    assert b.shape == (7, 5) and np.array_equal(a, b)
    lb.write_exr(path, a.astype(np.float64) + 1e-12)  # rounded to the file's float32
    assert np.array_equal(lb.read_exr(path), (a.astype(np.float64) + 1e-12).astype(np.float32))
