"""docs/python.md runs: its ```python blocks, in order, in one namespace, in a
scratch folder that sees the source tree's luminaires/ (the doc's paths are
relative to the source tree)."""

import os
import re

import matplotlib

from conftest import ROOT


def test_python_md_runs(tmp_path, monkeypatch):
    text = (ROOT / "docs" / "python.md").read_text()
    blocks = re.findall(r"^```python\n(.*?)^```", text, flags=re.S | re.M)
    assert len(blocks) >= 4, "docs/python.md lost its code blocks"
    matplotlib.use("Agg")
    os.symlink(ROOT / "luminaires", tmp_path / "luminaires")
    monkeypatch.chdir(tmp_path)
    ns = {}
    for i, code in enumerate(blocks):
        exec(compile(code, f"docs/python.md block {i + 1}", "exec"), ns)
    assert (tmp_path / "error-vs-time.png").stat().st_size > 1000
