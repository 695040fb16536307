#!/usr/bin/env bash
# Builds what the GPU machine runs and gathers it in build-dev-carry/ (git-ignored), for the
# `device` tool to carry: that machine has the CUDA driver and a C++ runtime but none of our
# Debian libraries, so this build leaves OpenImageIO and OpenColorIO out (PT_OIIO=OFF,
# PT_OCIO=OFF) and takes along the four small shared libraries the binaries still need, plus
# the shared assets the benchmark reads.
#
#   tests/render/backend/cuda/make_device_bundle.sh
#   then, on the device:  build-dev-carry/run.sh <command...>  (sets LD_LIBRARY_PATH, PT_SOURCE_DIR)
set -euo pipefail
cd "$(dirname "$0")/../.."
cmake -S . -B build-dev -G Ninja -DCMAKE_BUILD_TYPE=Release -DPT_CUDA=ON -DPT_OIIO=OFF -DPT_OCIO=OFF -DPT_EDITOR=OFF -DPT_TESTS=ON >/dev/null
cmake --build build-dev --target pt_cuda_tests pt-render
rm -rf build-dev-carry
mkdir -p build-dev-carry/lib build-dev-carry/assets
cp build-dev/tests/pt_cuda_tests build-dev/app/pt-render tests/render/backend/cuda/device_figures.sh build-dev-carry/
# Every shared library outside the C/C++ runtime and the dynamic loader.
ldd build-dev-carry/pt-render build-dev-carry/pt_cuda_tests | awk '/=> \// {print $3}' | sort -u |
  grep -v -E '/(libc|libm|libstdc\+\+|libgcc_s|libpthread|libdl|librt|ld-linux[^/]*)\.so' |
  while read -r lib; do cp -L "$lib" build-dev-carry/lib/; done
assets="${PT_SHARED_ASSETS:-$(pwd)/../shared/assets}"
for model in Balloon; do
  if [ -d "$assets/$model" ]; then cp -r "$assets/$model" build-dev-carry/assets/; fi
done
cat > build-dev-carry/run.sh <<'RUN'
#!/usr/bin/env bash
# Runs a bundled binary with its libraries and the project's files (the repository root).
here="$(cd "$(dirname "$0")" && pwd)"
export LD_LIBRARY_PATH="$here/lib${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}"
export PT_SOURCE_DIR="$(dirname "$here")"
export PT_SHARED_ASSETS="$here/assets"
exec "$@"
RUN
chmod +x build-dev-carry/run.sh
ls -la build-dev-carry build-dev-carry/lib
du -sh build-dev-carry
