#pragma once
// Numbers from tinygltf::Value objects (extension blocks such as KHR_materials_volume or
// KHR_texture_transform), each checked: when present it must be a number a float can hold,
// or an array of exactly `count` such numbers; InputErrors name "<element>.<key>".
// Internal to pt_assets.
#include <string>
#include <vector>

#include "assets/gltf/gltf_context.h"

namespace pt {

double gltfNumber(const GltfContext& ctx, const tinygltf::Value& object, const char* key, double fallback,
                  const std::string& element);

std::vector<double> gltfNumbers(const GltfContext& ctx, const tinygltf::Value& object, const char* key,
                                std::vector<double> fallback, const std::string& element);

// Core material factors parsed by tinygltf into std::vector<double>: `count` finite numbers.
void checkGltfNumbers(const GltfContext& ctx, const std::vector<double>& values, size_t count,
                      const std::string& element);

}  // namespace pt
