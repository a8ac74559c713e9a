#!/usr/bin/env bash
# check-format.sh [--fix] -- the C++ sources under host/, tests/ and python/ against .clang-format
# (clang-format 14, whose output the committed files match; another version formats a few
# constructs differently). Without --fix: lists the files that differ and exits 1.
# With --fix: formats them in place. The kernels are not checked (.clang-format says why).
set -euo pipefail
cd "$(dirname "$0")/.."
CF=${CLANG_FORMAT:-$(command -v clang-format-14 || command -v clang-format || true)}
if [[ -z $CF ]]; then
    echo "check-format.sh: clang-format 14 not found (scripts/install-deps.sh installs it)" >&2
    exit 2
fi
mapfile -t files < <(git ls-files 'host/*.cpp' 'host/*.h' 'tests/*.cpp' 'tests/*.h' 'python/*.cpp' 'python/*.h')
if [[ ${1:-} == --fix ]]; then
    "$CF" -i "${files[@]}"
    exit 0
fi
bad=()
for f in "${files[@]}"; do
    "$CF" --dry-run --Werror "$f" >/dev/null 2>&1 || bad+=("$f")
done
if ((${#bad[@]})); then
    echo "check-format.sh: ${#bad[@]} file(s) differ from .clang-format ($("$CF" --version | head -1)):" >&2
    printf '  %s\n' "${bad[@]}" >&2
    echo "run scripts/check-format.sh --fix" >&2
    exit 1
fi
echo "check-format.sh: ${#files[@]} files formatted as .clang-format says"
