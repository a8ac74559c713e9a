"""Bad input raises lumibench.InputError (a ValueError) with the command
line's message; a device failure lumibench.Error (a RuntimeError); the
interpreter goes on."""

import numpy as np
import pytest

import lumibench as lb
from conftest import LUM, cli_error

RENDER = ["render", "--luminaire", LUM, "--height", 1, "--rotation", "pi", "--res", 8, "--out"]


@pytest.fixture(scope="module")
def batwing():
    return lb.Luminaire.load(LUM)


@pytest.fixture(scope="module")
def scene():
    return lb.Scene(height=1.0, rotation="pi", res=8)


@pytest.mark.parametrize("spec", ["nosuchmethod", "mc:nosuchkey=1", "mc:n=0", "cubature:triangulation=square"])
def test_bad_spec_has_the_cli_message(batwing, scene, cli, tmp_path, spec):
    want = cli_error(cli(*RENDER, tmp_path / "x.exr", "--method", spec, check=False))
    with pytest.raises(lb.InputError) as e:
        lb.render(batwing, scene, spec)
    assert str(e.value) == want and isinstance(e.value, ValueError)


def test_missing_file_has_the_cli_message(cli, tmp_path):
    missing = str(tmp_path / "missing.ldt")
    want = cli_error(cli("luminaire", "info", missing, check=False))
    with pytest.raises(ValueError) as e:
        lb.Luminaire.load(missing)
    assert str(e.value) == want and missing in want


@pytest.mark.parametrize("flag,value", [("height", -1.0), ("res", 0), ("extent", -5.0), ("rotation", "7pi")])
def test_bad_scene_value_has_the_cli_message(cli, tmp_path, flag, value):
    args = dict(height=1.0, rotation="pi", res=8, extent=5.0)
    args[flag] = value
    cmd = ["render", "--luminaire", LUM, "--method", "point", "--out", tmp_path / "x.exr"]
    for k, v in args.items():
        cmd += [f"--{k}", v]
    want = cli_error(cli(*cmd, check=False))
    with pytest.raises(ValueError) as e:
        lb.Scene(**args)
    # The same message, naming the keyword where the CLI names its flag.
    assert want.startswith(f"--{flag}") and str(e.value) == want[2:]


@pytest.mark.parametrize(
    "array,what",
    [
        (np.zeros((4, 4), np.int32), "expected an array of float32 or float64, got dtype int32"),
        (np.zeros((4, 4), np.float16), "expected an array of float32 or float64, got dtype float16"),
        (np.zeros(16, np.float32), "expected a 2D array (rows x columns), got 1 dimensions"),
        (np.zeros((2, 4, 4), np.float64), "expected a 2D array (rows x columns), got 3 dimensions"),
        (np.zeros((0, 4), np.float32), "expected at least 1 x 1 pixels, got 0 x 4"),
        ([[1.0, 2.0]], "expected a 2D numpy array of float32 or float64, got list"),
    ],
)
def test_bad_array_names_what_was_wrong(array, what):
    ok = np.ones((4, 4), np.float32)
    with pytest.raises(ValueError) as e:
        lb.compare(ok, array)
    assert str(e.value) == "img: " + what
    with pytest.raises(ValueError) as e:
        lb.write_exr("/nonexistent/never.exr", array)
    assert str(e.value) == "array: " + what


def test_shape_mismatch_has_the_cli_message(cli, cli_json, tmp_path):
    a, b = tmp_path / "a.exr", tmp_path / "b.exr"
    lb.write_exr(str(a), np.ones((4, 4), np.float32))
    lb.write_exr(str(b), np.ones((4, 5), np.float32))
    want = cli_error(cli("compare", a, b, check=False))
    with pytest.raises(ValueError) as e:
        lb.compare(lb.read_exr(str(a)), lb.read_exr(str(b)))
    assert str(e.value) == want.replace(f"{a} vs {b}", "ref vs img")


def test_bad_keywords(batwing, scene):
    with pytest.raises(ValueError, match="^precision: "):
        lb.render(batwing, scene, "point", precision="half")
    with pytest.raises(ValueError, match=r"^size: expected \(W, L\) in metres or 'file', got 'big'$"):
        lb.Scene(height=1, rotation=1, size="big")
    with pytest.raises(ValueError, match="^alpha: only the specular scene"):
        lb.Scene(height=1, rotation=1, alpha=0.3)
    with pytest.raises(TypeError):  # a keyword the function does not have
        lb.render(batwing, scene, "point", nosuch=1)


def test_device_failure_is_a_runtime_error(batwing, scene, tmp_path, monkeypatch):
    # No kernel sources: the program cannot be built (lb::Error, the CLI's exit code 1).
    monkeypatch.setenv("LUMIBENCH_KERNEL_DIR", str(tmp_path))
    with pytest.raises(lb.Error) as e:
        lb.render(batwing, scene, "point")
    assert isinstance(e.value, RuntimeError) and not isinstance(e.value, ValueError)
    monkeypatch.delenv("LUMIBENCH_KERNEL_DIR")
    img, _ = lb.render(batwing, scene, "point", reps=1)  # the interpreter and the runtime go on
    assert img.shape == (8, 8)


def test_bad_device_index_has_the_cli_message(batwing, scene, cli, tmp_path):
    want = cli_error(cli(*RENDER, tmp_path / "x.exr", "--method", "point", "--device", 99, check=False))
    with pytest.raises(lb.InputError) as e:
        lb.render(batwing, scene, "point", device=99)
    assert str(e.value) == want
