"""Atomic figure output for the plotting scripts: the figure is written to a
temporary file beside the target and renamed over it only when savefig
returned, so an interrupted or failed write (a full disk) never leaves a
truncated PNG behind and keeps the old one (lumibench's C++ outputs do the
same: host/util/fileio.h). Standard library and matplotlib only."""
import os


def save_figure(fig, path, **kwargs):
    """fig.savefig(path, **kwargs), atomically. The format comes from the
    target's extension (the temporary's name has another one)."""
    path = os.fspath(path)
    directory = os.path.dirname(os.path.abspath(path))
    tmp = os.path.join(directory, f".{os.path.basename(path)}.tmp.{os.getpid()}")
    fmt = kwargs.pop("format", None) or os.path.splitext(path)[1].lstrip(".").lower() or "png"
    try:
        fig.savefig(tmp, format=fmt, **kwargs)
        with open(tmp, "rb") as f:
            os.fsync(f.fileno())
        os.replace(tmp, path)
    except BaseException:
        try:
            os.unlink(tmp)
        except FileNotFoundError:
            pass
        raise
