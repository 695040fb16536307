#!/usr/bin/env bash
# The GPU machine's whole session in one call (the device tool allows a few minutes a call):
# the CUDA tests, the robustness suite on the CUDA backend (the CPU one runs in CI), and converge runs (error
# against time) of the Cornell box and a shared asset against references rendered there on the
# GPU (PFM: that build writes no EXR). Every output lands in $OUT (default ./device-out).
#
#   tests/render/backend/cuda/make_device_bundle.sh      (here)
#   build-dev-carry/device_figures.sh     (there; the bundle script copies this file in)
# PARTS="tests stress converge" (the default) chooses what runs.
#
# The references must be far less noisy than the variants at the end of their run (a PFM
# carries no noise estimate for converge to subtract): each is rendered with the faster
# schedule for its scene, at several times the samples any variant reaches.
set -uo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
out="${OUT:-$(pwd)/device-out}"
mkdir -p "$out"
run() { "$here/run.sh" "$@"; }
render="$here/pt-render"
nvidia-smi --query-gpu=name,driver_version,memory.total --format=csv > "$out/gpu.txt" 2>&1

parts="${PARTS:-tests stress converge}"
if [[ " $parts " == *" tests "* ]]; then
    run "$here/pt_cuda_tests" > "$out/cuda_tests.txt" 2>&1
    echo "cuda tests: exit $?" | tee -a "$out/summary.txt"
fi
if [[ " $parts " == *" stress "* ]]; then
    run "$render" stress --backend cuda --csv "$out/stress.csv" > "$out/stress.txt" 2>&1
    echo "stress: exit $?" | tee -a "$out/summary.txt"
fi

converge() {  # NAME SCENE SIZE REFERENCE_SPP SECONDS [REFERENCE TOGGLES...]
    local name="$1" scene="$2" size="$3" spp="$4" seconds="$5"
    shift 5
    run "$render" reference "$scene" -o "$out/$name-ref.pfm" --spp "$spp" --size "$size" --backend cuda --quiet "$@" \
        > "$out/$name-reference.txt" 2>&1
    run "$render" converge "$scene" --reference "$out/$name-ref.pfm" --backend cuda --size "$size" \
        --time "$seconds" --variant naive:nee=off,mis=off,rr=off --variant full \
        --variant wavefront:megakernel=off --variant no-compaction:megakernel=off,compaction=off \
        --csv "$out/$name-converge.csv" --plot "$out/$name-converge.svg" --quiet > "$out/$name-converge.txt" 2>&1
    echo "converge $name: exit $?" | tee -a "$out/summary.txt"
}
[[ " $parts " == *" converge "* ]] || exit 0
converge cornell "$(dirname "$here")/scenes/cornell.json" 512x512 65536 8 --wavefront
if [ -f "$here/assets/Balloon/scene.gltf" ]; then
    converge balloon "$here/assets/Balloon/scene.gltf" 640x480 131072 8 --megakernel
fi
