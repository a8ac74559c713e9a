#!/usr/bin/env bash
# Puts the Python module built in build/python (docs/python.md) on the path of
# the project's .venv: a file lumibench.pth in its site-packages naming that
# folder (Python skips it while the folder does not exist, so this may run
# before the first build). install-deps.sh and build.sh call it. It leaves a
# .venv alone that is not this checkout's own (a git worktree whose .venv
# links to another checkout's), and says so; it never fails a build.
set -uo pipefail
cd "$(dirname "$0")/.."
[ -x .venv/bin/python ] || exit 0
if [[ $(realpath .venv) != "$(realpath .)"/* ]]; then
    echo "python-path: .venv is another checkout's; import this checkout's module with PYTHONPATH=$PWD/build/python"
    exit 0
fi
site=$(.venv/bin/python -c 'import sysconfig; print(sysconfig.get_paths()["purelib"])') || exit 0
pth="$site/lumibench.pth"
[ "$(cat "$pth" 2>/dev/null)" = "$PWD/build/python" ] && exit 0
if { echo "$PWD/build/python" >"$pth.tmp" && mv -f "$pth.tmp" "$pth"; } 2>/dev/null; then
    echo "python-path: $pth -> $PWD/build/python"
else
    rm -f "$pth.tmp" 2>/dev/null
    echo "python-path: cannot write $pth (run scripts/install-deps.sh as the owner of .venv);" \
         "import the module with PYTHONPATH=$PWD/build/python" >&2
fi
exit 0
