// Fuzz target: glTF import, text (.gltf) and binary (.glb), through loadScene as a model file
// is opened on its own: the GLB container and JSON checks, tinygltf's parser, accessors,
// meshes, morph targets, materials, embedded images (data URIs and bufferViews, decoded by
// our image readers), punctual lights, cameras and the node hierarchy, then the render compile
// of whatever loaded. Bytes that start with the GLB magic "glTF" are written as model.glb,
// all others as model.gltf. The folder holds no other file, so external URIs resolve to
// nothing but the input itself ("model.gltf" as a buffer).
#include <cstring>

#include "fuzz_load.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    const bool glb = size >= 4 && std::memcmp(data, "glTF", 4) == 0;
    pt::fuzz::loadAndCompile({glb ? "model.glb" : "model.gltf"}, data, size);
    return 0;
}
