// Fuzz target: OBJ import (obj_text_check, tinyobjloader, our corner/vertex merging, generated
// normals, MTL materials and their textures) through loadScene, then the render compile. The
// input is written both as model.obj and as model.mtl, so an input saying "mtllib model.mtl"
// is its own material library: the MTL reader skips the OBJ lines and the OBJ reader the MTL
// ones, and one input exercises both parsers (the seeds are OBJ and MTL text in one file).
#include "fuzz_load.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    pt::fuzz::loadAndCompile({"model.obj", "model.mtl"}, data, size);
    return 0;
}
