#pragma once
// Writes a GenScene as glTF 2.0: a .gltf JSON file and one external little-endian .bin beside
// it, both atomically. The .bin streams straight from the mesh's arrays (no second copy of
// the geometry), and the nodes stream into the JSON, so a 10-million-triangle mesh or a
// million instances cost their arrays and no more.
#include <string>

#include "pt_render/gen/gen_scene.h"
#include "render/util/progress.h"

namespace pt::cli {

// OUT.gltf -> OUT.bin.
std::string binPathFor(const std::string& gltfPath);

// Throws std::runtime_error naming the file when a write fails.
void writeGenGltf(const GenScene& scene, const std::string& gltfPath, const ProgressFn& progress = {});

}  // namespace pt::cli
