#!/bin/sh
# The sources follow .clang-format (issue 16): clang-format --dry-run --Werror over every C++ and
# CUDA source git tracks. The ctest test "format_check" runs it. Exit status: 0 when all are
# formatted; 1 with the first differences listed (run `git clang-format` or `clang-format -i` on
# the files named); 77 (ctest's skip) where clang-format or git is missing or the tree is not a
# git checkout. Regions a table reads better by hand are fenced with `// clang-format off`.
set -u
source_dir=$(cd "$(dirname "$0")/../.." && pwd)
formatter=$(command -v clang-format || command -v clang-format-14 || true)
if [ -z "$formatter" ] || ! command -v git > /dev/null; then
    echo "format_check: skipped: needs clang-format (Debian package clang-format) and git"
    exit 77
fi
# Versions format some constructs differently: the tree is formatted by Debian 12's clang-format 14.
if ! "$formatter" --version | grep -q "version 14\."; then
    echo "format_check: skipped: $("$formatter" --version) is not clang-format 14, which formatted the tree"
    exit 77
fi
cd "$source_dir" || exit 1
if ! git rev-parse --is-inside-work-tree > /dev/null 2>&1; then
    echo "format_check: skipped: $source_dir is not a git checkout"
    exit 77
fi
files=$(git ls-files '*.h' '*.cpp' '*.cu' '*.cuh')
# shellcheck disable=SC2086
report=$("$formatter" --dry-run --Werror $files 2>&1)
if [ -n "$report" ]; then
    echo "$report" | grep -E "error:" | head -20
    echo "format_check: $(echo "$report" | grep -c "error:") places differ from .clang-format ($($formatter --version))"
    exit 1
fi
echo "format_check: $(echo "$files" | wc -l) files follow .clang-format"
