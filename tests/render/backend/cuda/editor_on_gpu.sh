#!/usr/bin/env bash
# The editor on the GPU machine (issue 22): a GLX window drawn by NVIDIA's driver under a private
# Xvfb, rendered by the CUDA backend, frames handed to GL by CUDA-GL interop. Runs THERE, from the
# project root, in one `device` call:
#   here, once:  ../shared/tools/device-debs.sh                        (the build's packages)
#                tests/render/backend/cuda/editor_device_bundle.sh      (GLFW, ImGui, GL, Xvfb, Mesa)
#   there:       carry [".device-debs", ".device-editor", ".device"] and run
#                PT_SHARED_ASSETS=$(pwd)/.device/assets bash tests/render/backend/cuda/editor_on_gpu.sh
# (.device/assets: copies of the shared assets it opens, Balloon at least; the machine cannot
# reach ../shared.) What it does, each step's output in $OUT (default ./device-out):
#   1. unpacks both, over / without replacing a file that is there (the image's own libraries
#      stay), and builds pathtracer, the editor's tests, pt_editor_latency and pt-render with the
#      editor on and OpenImageIO/OpenColorIO off (not on that machine): the viewport then uses the
#      built-in sRGB view instead of an OCIO config, and screenshots and exports are PNG only;
#   2. runs the editor's unit and window tests (PT_EDITOR_TEST_BACKEND=cuda for the end-to-end
#      test: the same clicks, drags, undo and save as in CI, on the GPU);
#   3. runs pt_editor_latency (input event to swapped frame, per edit kind) on the Cornell box, the
#      Balloon asset and a generated 1M-triangle sphere with a morph target, screenshots of each,
#      and again with --no-frame-wait as the baseline.
# The window's GL must be NVIDIA's: the editor logs GL_RENDERER, and the summary prints it.
set -uo pipefail
out="${OUT:-$(pwd)/device-out}"
mkdir -p "$out"
S="$out/summary.txt"
log() { echo "$*" | tee -a "$S"; }
start=$(date +%s)
elapsed() { echo "$(($(date +%s) - start)) s"; }

# 1. Packages and the build.
for f in .device-debs/*.deb; do dpkg -x "$f" /; done
tar -xJf .device-editor/xbundle.tar.xz -C / --skip-old-files 2>/tmp/unpack.txt
mkdir -p /var/lib/xkb /tmp/.X11-unix && chmod 1777 /tmp/.X11-unix
ldconfig
B=/tmp/build-editor
if ! cmake -S . -B $B -G Ninja -DCMAKE_BUILD_TYPE=Release -DPT_CUDA=ON -DPT_OIIO=OFF -DPT_OCIO=OFF -DPT_EDITOR=ON \
    -DPT_TESTS=ON >/tmp/configure.txt 2>&1; then
    tail -30 /tmp/configure.txt
    exit 1
fi
if ! cmake --build $B -j16 --target pathtracer pt_editor_tests pt_editor_ui_tests pt_editor_latency pt-render \
    >/tmp/build.txt 2>&1; then
    grep -m20 -E "error:|undefined reference|FAILED" /tmp/build.txt
    exit 1
fi
log "build: $(elapsed)"
nvidia-smi --query-gpu=name,driver_version --format=csv,noheader | sed 's/^/GPU: /' | tee -a "$S"
# NVIDIA's GLX library, as libglvnd finds it by name (libGLX_nvidia.so.0).
if ! ldconfig -p | grep -q libGLX_nvidia; then
    nv=$(find / -xdev -name 'libGLX_nvidia.so.0' 2>/dev/null | head -1)
    [ -n "$nv" ] && export LD_LIBRARY_PATH="$(dirname "$nv"):${LD_LIBRARY_PATH:-}"
    log "libGLX_nvidia: ${nv:-not found}"
fi
export __GLX_VENDOR_LIBRARY_NAME=nvidia

# 2. The editor's tests on the CUDA backend.
T="$out/tests.txt"  # both programs' output (at most 8 files come back from the machine)
PT_EDITOR_TEST_BACKEND=cuda $B/tests/pt_editor_tests >/tmp/editor_tests.txt 2>&1
log "pt_editor_tests (end-to-end on cuda): exit $? ($(grep -c '^\[       OK' /tmp/editor_tests.txt) ok) $(elapsed)"
$B/tests/pt_editor_ui_tests >/tmp/editor_ui_tests.txt 2>&1
log "pt_editor_ui_tests (GL display shader vs CPU, on NVIDIA's GL): exit $? ($(grep -c '^\[       OK' /tmp/editor_ui_tests.txt) ok) $(elapsed)"
cat /tmp/editor_tests.txt /tmp/editor_ui_tests.txt >"$T"
grep -E "^\[  FAILED|SKIPPED|\[ measured" "$T" | head -12 | tee -a "$S"

# 3. Latency and screenshots.
assets="${PT_SHARED_ASSETS:-$(pwd)/.device/assets}"
$B/app/pt-render gen sphere --triangles 1000000 --morph -o /tmp/sphere1m.gltf --quiet >>"$S" 2>&1
latency() {  # NAME SCENE [driver options]
    local name=$1 scene=$2
    shift 2
    rm -rf "/tmp/latency-$name"
    timeout 300 $B/tests/pt_editor_latency "$scene" --backend cuda --size 1280x720 --runs 15 \
        --out "/tmp/latency-$name" "$@" >"/tmp/latency-$name.txt" 2>&1
    log "== $name: exit $? $(elapsed)"
    grep -v "^  editor" "/tmp/latency-$name.txt" | tee -a "$S"
    cat "/tmp/latency-$name/latency.jsonl" >>"$out/latency_logs.jsonl" 2>/dev/null
}
shot() { cp "/tmp/latency-$1/$2" "$out/$3" 2>/dev/null; }  # at most 8 files come back
# Each scene twice in the same run: as the editor swaps now, and with --no-frame-wait (its swap
# not waiting for the samples of that frame's edits: the baseline).
latency cornell scenes/cornell.json --object "glass sphere"
latency cornell_nowait scenes/cornell.json --object "glass sphere" --no-frame-wait
latency balloon "$assets/Balloon/scene.gltf"
latency balloon_nowait "$assets/Balloon/scene.gltf" --no-frame-wait
latency sphere1m /tmp/sphere1m.gltf
latency sphere1m_nowait /tmp/sphere1m.gltf --no-frame-wait
# The editor's default: the render follows the viewport (a lower resolution while the camera
# moves), and the driver's last step resizes the window (interop buffers follow).
latency balloon_follow "$assets/Balloon/scene.gltf" --follow-viewport
shot cornell shot.png cornell.png
shot cornell shot-1.png cornell_end.png
shot balloon shot.png balloon.png
shot sphere1m shot-1.png sphere1m_end.png
shot balloon_follow shot-2.png balloon_resized.png
log "done: $(elapsed)"
