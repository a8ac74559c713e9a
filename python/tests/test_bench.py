"""lb.bench: the document of `lumibench bench --json` as a dict."""

import pytest

import lumibench as lb
from conftest import LUM


def test_bench_quick():
    # The smallest run (--quick at 32^2, one rep and round): ~12 s of CPU.
    doc = lb.bench(luminaire=LUM, res=32, reps=1, rounds=1, samples=4, quick=True)
    assert {"device", "res", "methods", "mc", "mc_fit", "cubature", "luminaire", "scene"} <= set(doc)
    assert doc["res"] == 32 and doc["device"] == lb.devices()[0]["name"]
    assert doc["methods"] and all(m["time_ms"] > 0 for m in doc["methods"])


@pytest.mark.parametrize("kw,msg", [({"local": "0x3"}, "local: work-group 0x3 out of range"),
                                    ({"local": "big"}, "local: expected WxH, got 'big'"),
                                    ({"res": 0}, "res: expected an integer in [1, 16384], got 0")])
def test_bench_bad_input(kw, msg):
    with pytest.raises(ValueError) as e:
        lb.bench(**kw)
    assert str(e.value) == msg
