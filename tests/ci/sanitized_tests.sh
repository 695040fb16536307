#!/bin/bash
# The second compiler and the sanitizer job (issue 16): builds the CPU libraries and their unit
# tests with clang++ under AddressSanitizer + UndefinedBehaviorSanitizer (PT_SANITIZE) in a build
# folder of its own, and runs them; any sanitizer report fails the test it happens in. The CUDA
# backend, the editor window and the CLI-driven tests are left to the main (g++) build: nvcc has
# no sanitizer, and the CLI tests spawn a program per case, which sanitizers make minutes slower.
# The ctest test "sanitized_cpu_tests" runs it.
#
# Usage: tests/ci/sanitized_tests.sh BUILD_DIR
# Exit status: 0 when every test passed clean; 1 on a build failure, a failed test or a
# sanitizer report; 77 (ctest's skip) where clang++ is missing.
set -u
if [ $# -ne 1 ]; then
    echo "usage: $0 BUILD_DIR" >&2
    exit 2
fi
source_dir=$(cd "$(dirname "$0")/../.." && pwd)
build_dir=$(mkdir -p "$1" && cd "$1" && pwd)
cxx=$(command -v clang++ || command -v clang++-14 || true)
cc=$(command -v clang || command -v clang-14 || true)
if [ -z "$cxx" ] || [ -z "$cc" ]; then
    echo "sanitized: skipped: no clang++ (Debian package clang)"
    exit 77
fi

generator=()
command -v ninja >/dev/null && [ ! -f "$build_dir/CMakeCache.txt" ] && generator=(-G Ninja)
start=$(date +%s)
if ! cmake -S "$source_dir" -B "$build_dir" "${generator[@]}" -DCMAKE_BUILD_TYPE=Release \
        -DCMAKE_CXX_COMPILER="$cxx" -DCMAKE_C_COMPILER="$cc" -DPT_SANITIZE=ON -DPT_CUDA=OFF \
        -DPT_EDITOR=OFF >"$build_dir/configure.log" 2>&1; then
    cat "$build_dir/configure.log"
    echo "sanitized: FAILED: configuring the clang build"
    exit 1
fi
targets="pt_render_tests pt_assets_tests pt_editor_tests"
# shellcheck disable=SC2086
if ! cmake --build "$build_dir" --target $targets >"$build_dir/build.log" 2>&1; then
    grep -E "error" -A3 "$build_dir/build.log" | head -n 60
    echo "sanitized: FAILED: building with $("$cxx" --version | head -n 1)"
    exit 1
fi
echo "sanitized: built with $("$cxx" --version | head -n 1) in $(($(date +%s) - start)) s"

# Every report is fatal; leaks are reported at exit. Test programs write under their own TMPDIR.
export ASAN_OPTIONS="detect_leaks=1:abort_on_error=0:symbolize=1:strict_string_checks=1"
export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1"
failed=0
for target in $targets; do
    start=$(date +%s)
    work="$build_dir/run/$target"
    rm -rf "$work"
    mkdir -p "$work"
    run() { TMPDIR="$work" "$build_dir/tests/$target" --gtest_brief=1 >"$work/log" 2>&1; }
    run
    status=$?
    # LeakSanitizer's own tracer can crash (ptrace under a loaded machine: "Tracer caught
    # signal 11 ... LeakSanitizer has encountered a fatal error"), after every test passed; seen
    # in CI at exit, before the test programs ran the check themselves (tests/support/
    # test_main.cpp). That is no report about our code: the program runs once more.
    if [ $status -ne 0 ] && grep -q "LeakSanitizer has encountered a fatal error" "$work/log" &&
        ! grep -qE "\[  FAILED  \]|ERROR: AddressSanitizer|runtime error:|ERROR: LeakSanitizer: detected" "$work/log"; then
        echo "sanitized: $target: LeakSanitizer's tracer crashed after the tests passed; running it again"
        mv "$work/log" "$work/log.tracer-crash"
        run
        status=$?
    fi
    if [ $status -eq 0 ]; then
        echo "sanitized: $target: $(grep -o '[0-9]* tests\? from [0-9]* test suites\? ran' "$work/log" | head -n 1), clean, in $(($(date +%s) - start)) s"
    else
        # The tracer says why it stopped on the lines before LeakSanitizer's own.
        grep -E "FAILED|ERROR: AddressSanitizer|runtime error:|LeakSanitizer" -B3 -A12 "$work/log" | head -n 80
        echo "sanitized: $target: FAILED (log: $work/log)"
        failed=1
    fi
done
exit $failed
