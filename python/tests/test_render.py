"""lb.render against `lumibench render`: the same image, bit for bit, and the
same description of what was rendered."""

import numpy as np
import pytest

import lumibench as lb
from conftest import LUM

METHODS = ["point", "cubature", "mc:n=8"]


@pytest.fixture(scope="module")
def batwing():
    return lb.Luminaire.load(LUM)


@pytest.mark.parametrize("precision", ["float", "double"])
@pytest.mark.parametrize("spec", METHODS)
def test_render_equals_cli_exr(batwing, cli_json, tmp_path, spec, precision):
    scene = lb.Scene(height=1.0, rotation="3pi/4", res=24)
    img, info = lb.render(batwing, scene, spec, precision=precision, reps=1)
    out = tmp_path / "cli.exr"
    doc = cli_json("render", "--luminaire", LUM, "--method", spec, "--height", 1.0, "--rotation", "3pi/4",
                   "--res", 24, "--precision", precision, "--reps", 1, "--out", out, "--json")
    exr = lb.read_exr(str(out))
    assert exr.dtype == np.float32 and exr.shape == (24, 24)
    want = np.float64 if precision == "double" else np.float32
    assert img.dtype == want and img.shape == (24, 24)
    assert img.flags.c_contiguous and img.flags.owndata is False and img.flags.writeable
    # The EXR channel is FLOAT: the CLI writes a double image rounded to
    # float32, so the double array rounded the same way must give its bits.
    assert np.array_equal(img.astype(np.float32).view(np.uint32), exr.view(np.uint32))
    # The image is not trivial (a constant or empty image would pass the above).
    assert np.ptp(exr) > 0 and np.all(np.isfinite(exr))
    for key in ("method", "spec", "params", "scene", "device", "precision", "nonfinite"):
        assert info[key] == doc[key], key
    assert info["time_ms"]["reps"] == 1 and info["time_ms"]["median"] > 0


def test_seed_is_the_method_parameter(batwing):
    scene = lb.Scene(height=1.0, rotation="3pi/4", res=16)
    a, ia = lb.render(batwing, scene, "mc:n=4", seed=3, reps=1)
    b, ib = lb.render(batwing, scene, "mc:n=4,seed=3", reps=1)
    c, _ = lb.render(batwing, scene, "mc:n=4", seed=4, reps=1)
    assert ia["spec"] == ib["spec"] and np.array_equal(a, b)
    assert not np.array_equal(a, c)  # another draw of the shared sample set
    with pytest.raises(ValueError, match="seed"):
        lb.render(batwing, scene, "point", seed=1)


def test_reference_has_its_error_estimate(batwing, cli, tmp_path):
    scene = lb.Scene(height=1.0, rotation="3pi/4", res=16)
    ref, err, info = lb.reference(batwing, scene, spec="reference:tol=1e-3", cache=False)
    out = tmp_path / "ref.exr"
    cli("render", "--luminaire", LUM, "--method", "reference:tol=1e-3", "--height", 1, "--rotation", "3pi/4",
        "--res", 16, "--no-cache", "--out", out)
    assert np.array_equal(ref, lb.read_exr(str(out)))
    assert np.array_equal(err, lb.read_exr(str(tmp_path / "ref.err.exr")))
    assert info["method"] == "reference" and np.all(err >= 0) and np.any(err > 0)


def test_luminaire_table(batwing, cli_json):
    doc = cli_json("luminaire", "info", LUM, "--json")
    assert batwing.format == doc["format"] and batwing.symmetry == doc["symmetry"]
    assert batwing.flux_lm == pytest.approx(doc["flux_lm"], rel=1e-12)  # one computation, printed with 17 digits
    assert batwing.max_cd == doc["max_cd"]
    assert batwing.candela.shape == (doc["c_planes"], doc["gammas"])
    assert batwing.opening_shape == doc["shape"]
    assert batwing.opening_size == (doc["length_m"], doc["width_m"], doc["height_m"])
    assert batwing.c[0] == 0 and batwing.c[-1] == 360 and not batwing.candela.flags.writeable
    # The table is the one the kernels look up: at grid points the bilinear lookup returns the entry.
    i, j = len(batwing.c) // 3, len(batwing.gamma) // 2
    assert batwing.intensity(batwing.c[i], batwing.gamma[j]) == pytest.approx(batwing.candela[i, j], rel=1e-12)


def test_scene_keywords_and_defaults():
    s = lb.Scene(height=0.5, rotation=np.pi)
    assert (s.res, s.extent, s.size, s.shape, s.kind) == (256, 5.0, (1.0, 1.0), "rect", "diffuse")
    assert lb.Scene(height=1, rotation="3pi/4").rotation == pytest.approx(3 * np.pi / 4, rel=1e-15)
    assert lb.Scene(height=1, rotation=2, size="file").size == "file"


def test_methods_and_devices():
    ms = {m["name"]: m for m in lb.methods()}
    assert {"reference", "point", "mc", "cubature", "voronoi", "robust"} <= set(ms)
    n = {p["name"]: p for p in ms["mc"]["params"]}["n"]
    assert n["kind"] == "int" and n["min"] >= 1 and int(n["default"]) >= 1
    devs = lb.devices()
    assert devs and sum(d["default"] for d in devs) == 1


def test_reference_cache_is_the_clis(batwing, cli, tmp_path, monkeypatch):
    # A reference the CLI rendered is read back by the module, not rendered again.
    monkeypatch.setenv("LUMIBENCH_CACHE", str(tmp_path / "cache"))
    scene = lb.Scene(height=2.0, rotation="5pi/8", res=12)
    args = ["--luminaire", LUM, "--method", "reference:tol=1e-3", "--height", 2, "--rotation", "5pi/8", "--res", 12]
    cli("render", *args, "--out", tmp_path / "ref.exr")
    ref, err, info = lb.reference(batwing, scene, spec="reference:tol=1e-3")
    assert info["cached"] is True
    assert np.array_equal(ref, lb.read_exr(str(tmp_path / "ref.exr")))
    monkeypatch.setenv("LUMIBENCH_CACHE", str(tmp_path / "empty"))
    assert lb.reference(batwing, scene, spec="reference:tol=1e-3")[2]["cached"] is False
