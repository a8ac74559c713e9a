"""lumibench: photometric polygonal lights from Python, numpy in, numpy out.

The functions are a thin shell over the libraries `build/lumibench` links
(docs/python.md): the same methods, the same kernels, the same checks and
messages. Images are C-contiguous numpy arrays (res x res, E in lux, row 0 at
the top), float32 for precision 'float' and float64 for 'double'.

    >>> import lumibench as lb
    >>> lum = lb.Luminaire.load("luminaires/batwing.ldt")
    >>> scene = lb.Scene(height=1.0, rotation="3pi/4", res=64)
    >>> img, info = lb.render(lum, scene, "cubature")
    >>> ref, err, _ = lb.reference(lum, scene)
    >>> lb.compare(ref, img)["nmse"]

Bad input raises lumibench.InputError (a ValueError) with the command line's
message; device failures lumibench.Error (a RuntimeError).
"""

from __future__ import annotations

import json as _json
import os as _os
import tempfile as _tempfile
from typing import Any, Mapping, Optional, Union

from ._core import (  # noqa: F401  (the public API)
    Error,
    InputError,
    Luminaire,
    Scene,
    __version__,
    bench,
    compare,
    devices,
    methods,
    read_exr,
    reference,
    render,
    write_exr,
)
from . import _core

__all__ = [
    "Error",
    "InputError",
    "Luminaire",
    "Scene",
    "bench",
    "compare",
    "devices",
    "methods",
    "read_exr",
    "reference",
    "render",
    "run",
    "write_exr",
]


def _experiment_file(experiment: Mapping[str, Any], out: str) -> str:
    """Writes an experiment given as a dict to OUT/experiment.json (atomically)."""
    _os.makedirs(out, exist_ok=True)
    path = _os.path.join(out, "experiment.json")
    fd, tmp = _tempfile.mkstemp(dir=out, prefix=".experiment.json.")
    try:
        with _os.fdopen(fd, "w") as f:
            _json.dump(dict(experiment), f, indent=2)
        _os.replace(tmp, path)
    except BaseException:
        _os.unlink(tmp)
        raise
    return path


def run(
    experiment: Union[str, "_os.PathLike[str]", Mapping[str, Any]],
    out: Union[str, "_os.PathLike[str]"],
    *,
    luminaires: Optional[str] = None,
    shard: str = "1/1",
    res: Optional[int] = None,
    reps: Optional[int] = None,
    time_res: Optional[int] = None,
    seeds: Optional[int] = None,
    device: Optional[int] = None,
    report: bool = True,
    progress: bool = False,
):
    """run(experiment, out, *, luminaires=None, shard='1/1', res=None, reps=None, time_res=None,
        seeds=None, device=None, report=True, progress=False) -> pandas.DataFrame

    Runs an experiment as `lumibench run EXPERIMENT --out OUT` does and returns
    OUT/results.csv as a DataFrame: one row per record, the columns of the
    file (docs/experiments.md). `experiment` is a file (experiments/*.json) or
    the same object as a dict (written to OUT/experiment.json first, so that
    the run can be repeated from the command line). A rerun resumes. The
    keywords are the command's flags (None: the experiment's value):
    luminaires (--luminaires DIR), shard ('K/N'), res, reps, time_res, seeds,
    device; report=False is --no-report; progress=True prints the progress
    lines on stderr. The attribute `attrs['summary']` of the frame holds the
    run's counts (cells computed, skipped, seconds).
    """
    import pandas

    out = _os.fspath(out)
    _core._check_out_dir(out)
    if isinstance(experiment, Mapping):
        path = _experiment_file(experiment, out)
    else:
        path = _os.fspath(experiment)
    summary = _core._run(path, out, luminaires or "", shard, res, reps, time_res, seeds, device, report, progress)
    frame = pandas.read_csv(_os.path.join(out, "results.csv"))
    frame.attrs["summary"] = summary
    return frame
