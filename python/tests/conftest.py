"""Shared fixtures of the Python module's tests (docs/python.md): the source
tree, the CLI built beside the module (build/lumibench), and a runner for it."""

import json
import os
import pathlib
import subprocess

import pytest

ROOT = pathlib.Path(__file__).resolve().parents[2]
CLI = ROOT / "build" / "lumibench"
LUM = str(ROOT / "luminaires" / "batwing.ldt")


@pytest.fixture(scope="session")
def cli():
    """cli(*args) -> CompletedProcess of build/lumibench (text, never a shell)."""
    if not CLI.exists():
        pytest.fail(f"{CLI} is missing: run scripts/build.sh")

    def run(*args, check=True):
        p = subprocess.run([str(CLI), *map(str, args)], capture_output=True, text=True)
        if check and p.returncode != 0:
            raise AssertionError(f"lumibench {' '.join(map(str, args))} failed ({p.returncode}): {p.stderr}")
        return p

    return run


@pytest.fixture(scope="session")
def cli_json(cli):
    return lambda *args: json.loads(cli(*args).stdout)


def cli_error(p):
    """The message of a failed CLI run: its stderr without the 'lumibench: error: ' prefix."""
    assert p.returncode == 2, p.stderr
    line = p.stderr.strip().splitlines()[-1]
    prefix = "lumibench: error: "
    assert line.startswith(prefix), line
    return line[len(prefix):]
