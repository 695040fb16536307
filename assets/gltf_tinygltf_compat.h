#pragma once
// Rewrites of a glTF's JSON, before tinygltf 2.7 parses it, for valid files it would reject:
//  - KHR_draco_mesh_compression: a primitive's indices accessor has no bufferView (its values
//    are in the Draco data), and tinygltf fails on that ("accessor[N] invalid bufferView").
//    The primitive's "indices" moves into its extension object (as "indices"), where
//    gltf_draco.cpp finds it.
// Internal to pt_assets.
#include <nlohmann/json.hpp>

namespace pt {

// True where `root` was changed.
bool adaptGltfForTinygltf(nlohmann::json& root);

}  // namespace pt
