#pragma once
// Rewrites of a glTF's JSON, before tinygltf 2.7 parses it, for valid files it would reject:
//  - KHR_draco_mesh_compression: a primitive's indices accessor has no bufferView (its values
//    are in the Draco data), and tinygltf fails on that ("accessor[N] invalid bufferView").
//    The primitive's "indices" moves into its extension object (as "indices"), where
//    gltf_draco.cpp finds it.
//  - EXT_meshopt_compression: a fallback buffer (one whose views are all compressed into
//    another) may have no uri and no bytes; tinygltf fails on a buffer without a uri outside a
//    .glb, and in a .glb gives it the BIN chunk's bytes or fails. It becomes a data URI of four
//    zero bytes (tinygltf decodes no empty one).
// Internal to pt_assets.
#include <nlohmann/json.hpp>

namespace pt {

// Four zero bytes as a data URI: what stands in, for tinygltf, for bytes it must not read
// (it decodes no empty data URI).
inline constexpr const char* kTinygltfStandInUri = "data:application/octet-stream;base64,AAAAAA==";

// `buffer` as tinygltf is to see it: those four bytes in place of its own.
void standInForTinygltf(nlohmann::json& buffer);

// A buffer marked {"extensions": {"EXT_meshopt_compression": {"fallback": true}}}.
bool isMeshoptFallbackBuffer(const nlohmann::json& buffer);

// True where `root` was changed.
bool adaptGltfForTinygltf(nlohmann::json& root);

}  // namespace pt
