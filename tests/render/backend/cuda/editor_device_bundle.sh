#!/usr/bin/env bash
# Packs what the editor needs on the GPU machine (issue 22) into the git-ignored .device-editor/,
# which the `device` tool carries (carry: [".device-debs", ".device-editor"]). That machine's
# CUDA image has the compiler, CMake and NVIDIA's driver libraries (libGLX_nvidia among them) but
# no X server, no GLFW, no Dear ImGui and no OpenGL headers. Run here, from the project root,
# after .ci/setup (the packages come from this machine's own installed files):
#   tests/render/backend/cuda/editor_device_bundle.sh
# The bundle holds:
#   - to build the editor: GLFW 3.3 (headers, CMake config, library), Dear ImGui 1.86 (headers,
#     backends, static library, pkg-config file), the GL/GLX/KHR headers and libglvnd's
#     libraries with their development links;
#   - to run it: Xvfb, its keymap compiler and data, and Mesa's swrast DRI driver with its
#     libraries (LLVM among them: about 40 of the 48 MB). Xvfb's GLX extension needs a DRI
#     provider to start at all; the window's own context then comes from NVIDIA's libGLX
#     (__GLX_VENDOR_LIBRARY_NAME=nvidia), which editor_on_gpu.sh checks through GL_RENDERER;
#   - xdotool, which the editor's end-to-end test and the latency driver send input with.
# Libraries are the ldd closure of those programs, less the ones every Ubuntu/Debian base image
# has (glibc, libstdc++, zlib, ...). editor_on_gpu.sh unpacks it over / without replacing any
# file that exists there.
set -euo pipefail
dir=.device-editor
mkdir -p "$dir" .git/info
grep -qx "/$dir/" .git/info/exclude 2>/dev/null || echo "/$dir/" >> .git/info/exclude
lib=/usr/lib/x86_64-linux-gnu
programs=("$(command -v Xvfb)" "$(command -v xkbcomp)" "$(command -v xdotool)"
          $lib/dri/swrast_dri.so $lib/libGLX_mesa.so.0 $lib/libglfw.so.3 $lib/libOpenGL.so.0 $lib/libGL.so.1
          $lib/libGLX.so.0 $lib/libEGL.so.1)
for p in "${programs[@]}"; do [ -e "$p" ] || { echo "missing $p: run .ci/setup first" >&2; exit 1; }; done
base='/(libc|libm|libdl|libpthread|librt|libstdc\+\+|libgcc_s|libz|libzstd|liblzma|libsystemd|libgcrypt|libgpg-error|libcap|libselinux|libpcre2-8|liblz4|libaudit|libtinfo|libffi|ld-linux-x86-64)\.so'
list=$(mktemp)
for p in "${programs[@]}"; do
  echo "$p"
  ldd "$p" | awk '$3 ~ /^\// {print $3}' | grep -Ev "$base" || true
done | sort -u > "$list"
# Each library under its soname link and its real file; the development files by package.
while read -r f; do echo "$f"; readlink -f "$f"; done < "$list" > "$list.all"
dpkg -L libglfw3-dev libimgui-dev libgl-dev libglx-dev libopengl-dev libegl-dev xkb-data 2>/dev/null |
  grep -E '^/usr/(include|lib|share/X11/xkb)' | while read -r f; do [ -f "$f" ] || [ -L "$f" ] && echo "$f"; done >> "$list.all"
sort -u "$list.all" | grep -v '^/usr/share/doc' > "$list"
tar -cf - --files-from "$list" 2>/dev/null | xz -9 -T0 > "$dir/xbundle.tar.xz"
echo "$(wc -l < "$list") files, $(du -h "$dir/xbundle.tar.xz" | cut -f1) in $dir/xbundle.tar.xz"
rm -f "$list" "$list.all"
