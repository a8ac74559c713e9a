"""Atomic figure and text output for the plotting scripts: the file is written to a
temporary file beside the target and renamed over it only when the write
returned, so an interrupted or failed write (a full disk) never leaves a
truncated file behind and keeps the old one (lumibench's C++ outputs do the
same: host/util/fileio.h). Standard library and matplotlib only."""
import os


def _write_atomically(path, write):
    """Calls write(tmp) for a temporary beside path, fsyncs it and renames it
    over path; removes the temporary on any failure."""
    path = os.fspath(path)
    directory = os.path.dirname(os.path.abspath(path))
    tmp = os.path.join(directory, f".{os.path.basename(path)}.tmp.{os.getpid()}")
    try:
        write(tmp)
        with open(tmp, "rb") as f:
            os.fsync(f.fileno())
        os.replace(tmp, path)
    except BaseException:
        try:
            os.unlink(tmp)
        except FileNotFoundError:
            pass
        raise


def save_figure(fig, path, **kwargs):
    """fig.savefig(path, **kwargs), atomically. The format comes from the
    target's extension (the temporary's name has another one)."""
    fmt = kwargs.pop("format", None) or os.path.splitext(os.fspath(path))[1].lstrip(".").lower() or "png"
    _write_atomically(path, lambda tmp: fig.savefig(tmp, format=fmt, **kwargs))


def write_text(path, text):
    """Writes text to path atomically, as save_figure."""
    def write(tmp):
        with open(tmp, "w") as f:
            f.write(text)
    _write_atomically(path, write)


def emit_text(text, path=None):
    """The Markdown a table script makes: to path (atomically) when given, else to stdout."""
    if path:
        write_text(path, text)
    else:
        import sys
        sys.stdout.write(text)
