#pragma once
// Google's Draco mesh decoder (Debian's libdraco-dev), loaded on first use from a module of
// ours, pt_draco (draco_module.cpp), with dlopen and RTLD_LOCAL: libdraco also exports the
// tinygltf and stb it bundles for its transcoder, and linked into the programs those took the
// place of our tinygltf's and stb's (a different tinygltf build: every glTF import crashed).
// Built where libdraco is found; gltf_draco.h turns what it decodes into accessor values.
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace pt {

// A decoded Draco mesh, free of Draco's types: every attribute as floats (integer attributes
// converted, normalized ones to [0, 1] or [-1, 1], as the bitstream marks them).
struct DracoMesh {
    struct Attribute {
        uint32_t id = 0;  // the attribute's unique id, which glTF's extension names
        int components = 0;
        std::vector<float> values;  // components a point
    };
    uint32_t points = 0;
    std::vector<uint32_t> corners;  // three a triangle, each a point index
    std::vector<Attribute> attributes;
    std::string error;  // not empty: the bitstream could not be decoded, and why
};

struct DracoDecoder {
    DracoMesh (*decode)(const uint8_t* bytes, size_t size);
};

// The module's functions; opens it on the first call. Throws InputError where it cannot.
const DracoDecoder& dracoDecoder();

}  // namespace pt

// The one symbol the module exports: its table of functions (a DracoDecoder), typed as
// plugin_module.h calls it.
extern "C" const void* ptDracoDecoder();
