#!/bin/bash
# Builds the fuzz targets with clang (ASan + UBSan + libFuzzer) in a build folder of their own
# and runs each for a bounded time over a copy of tests/fuzz/corpus/<target>, two at a time.
# The ctest test "fuzz_loaders" runs it; README.md in this folder says how to fuzz for longer.
#
# Usage: tests/fuzz/run_fuzz.sh BUILD_DIR [SECONDS_PER_TARGET]   (default 60)
# Environment: PT_FUZZ_OIIO=ON decodes images through OpenImageIO, as the default program
# build does (default OFF: stb, which every build has; see README.md for the tradeoff).
# Exit status: 0 when every target ran clean; 1 on any crash, leak, sanitizer report,
# per-input timeout or memory limit (the input is saved and its path printed); 77 (ctest's
# skip) where clang++ or its libFuzzer runtime is missing. Writes nothing into the source tree.
set -u

if [ $# -lt 1 ] || [ $# -gt 2 ]; then
    echo "usage: $0 BUILD_DIR [SECONDS_PER_TARGET]" >&2
    exit 2
fi
source_dir=$(cd "$(dirname "$0")/../.." && pwd)
build_dir=$(mkdir -p "$1" && cd "$1" && pwd)
seconds=${2:-60}
targets="fuzz_gltf fuzz_obj fuzz_scene_json fuzz_image fuzz_pfm"

# --- toolchain: skip (77) where clang++ or libFuzzer is missing --------------------------------
cxx=$(command -v clang++ || command -v clang++-14 || true)
if [ -z "$cxx" ]; then
    echo "fuzz: skipped: no clang++ (Debian packages clang and libclang-rt-14-dev)"
    exit 77
fi
probe="$build_dir/probe"
mkdir -p "$probe"
printf '#include <cstddef>\n#include <cstdint>\nextern "C" int LLVMFuzzerTestOneInput(const uint8_t*, size_t) { return 0; }\n' \
    >"$probe/probe.cpp"
if ! "$cxx" -fsanitize=fuzzer,address,undefined "$probe/probe.cpp" -o "$probe/probe" 2>"$probe/log"; then
    echo "fuzz: skipped: $cxx cannot link -fsanitize=fuzzer (Debian package libclang-rt-14-dev):"
    cat "$probe/log"
    exit 77
fi

# --- build: only the fuzz targets and what they link -------------------------------------------
generator=()
command -v ninja >/dev/null && [ ! -f "$build_dir/CMakeCache.txt" ] && generator=(-G Ninja)
start=$(date +%s)
if ! cmake -S "$source_dir" -B "$build_dir" "${generator[@]}" -DCMAKE_BUILD_TYPE=RelWithDebInfo \
        -DCMAKE_CXX_COMPILER="$cxx" -DPT_FUZZ=ON -DPT_CUDA=OFF -DPT_EDITOR=OFF -DPT_TESTS=OFF \
        -DPT_OCIO=OFF -DPT_OIIO="${PT_FUZZ_OIIO:-OFF}" >"$build_dir/configure.log" 2>&1; then
    cat "$build_dir/configure.log"
    echo "fuzz: FAILED: configuring the fuzz build"
    exit 1
fi
if ! cmake --build "$build_dir" --target pt_fuzz_targets >"$build_dir/build.log" 2>&1; then
    tail -n 60 "$build_dir/build.log"
    echo "fuzz: FAILED: building the fuzz targets"
    exit 1
fi
echo "fuzz: configured and built in $(($(date +%s) - start)) s"

# --- run: each target for $seconds over a fresh copy of its corpus -----------------------------
# Longest input per target: a little over the largest seed, so mutations can grow it.
max_len() {
    case $1 in
        fuzz_gltf | fuzz_scene_json) echo 32768 ;;
        fuzz_image) echo 16384 ;;
        *) echo 4096 ;;
    esac
}
dict() {
    case $1 in
        fuzz_gltf | fuzz_scene_json) echo "-dict=$source_dir/tests/fuzz/json.dict" ;;
        fuzz_obj) echo "-dict=$source_dir/tests/fuzz/obj.dict" ;;
    esac
}

run_target() {
    local target=$1 work="$build_dir/run/$1"
    rm -rf "$work"
    mkdir -p "$work/tmp"
    cp -r "$source_dir/tests/fuzz/corpus/$target" "$work/corpus"
    # Temp files of the targets go under $work/tmp (test::tempDir() is under $TMPDIR).
    TMPDIR="$work/tmp" \
        ASAN_OPTIONS="detect_leaks=1:abort_on_error=0:symbolize=1" \
        UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1" \
        "$build_dir/tests/fuzz/$target" "$work/corpus" $(dict "$target") \
        -max_total_time="$seconds" -max_len="$(max_len "$target")" -timeout=30 \
        -rss_limit_mb=2560 -artifact_prefix="$work/" -print_final_stats=1 >"$work/log" 2>&1
}

report() {
    local target=$1 status=$2 work="$build_dir/run/$1"
    if [ "$status" -eq 0 ]; then
        local execs cov
        execs=$(grep -o 'stat::number_of_executed_units: *[0-9]*' "$work/log" | grep -o '[0-9]*$')
        cov=$(grep -o 'cov: [0-9]*' "$work/log" | tail -n 1)
        echo "fuzz: $target: clean, ${execs:-?} inputs in ${seconds} s, ${cov:-cov: ?}"
        return 0
    fi
    tail -n 80 "$work/log"
    echo "fuzz: $target: FAILED (libFuzzer exit $status); input saved as:" $(ls "$work"/crash-* \
        "$work"/leak-* "$work"/timeout-* "$work"/oom-* 2>/dev/null)
    echo "fuzz: reproduce with: $build_dir/tests/fuzz/$target <input>"
    return 1
}

failed=0
set -- $targets
while [ $# -gt 0 ]; do
    first=$1
    second=${2:-}
    run_target "$first" &
    first_pid=$!
    if [ -n "$second" ]; then
        run_target "$second" &
        second_pid=$!
    fi
    wait "$first_pid"
    first_status=$?
    report "$first" "$first_status" || failed=1
    if [ -n "$second" ]; then
        wait "$second_pid"
        second_status=$?
        report "$second" "$second_status" || failed=1
        shift
    fi
    shift
done
# libFuzzer's own exit code for a crash is 77, ctest's skip: every failure exits 1.
exit "$failed"
