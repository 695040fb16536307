#pragma once
// Scene features, host side: which features a compiled scene uses, and their names. The bits
// themselves, and what they mean to per-ray code, are in feature_set.h.
#include <cstdint>
#include <string>
#include <vector>

#include "render/kernel/feature_set.h"

namespace pt {

struct CompiledScene;

// The features of a compiled scene (everything but kAovs and kBruteForce, which the backend
// adds from its toggles and outputs). O(materials + lights): cheap enough after every edit.
FeatureSet sceneFeatures(const CompiledScene& scene, bool morphTargets);

// Stable snake_case names, in bit order ("base_color_texture", ...), for info, stats JSON and
// the editor.
const char* featureName(FeatureSet bit);
std::vector<std::string> featureNames(FeatureSet features);
// "base_color_texture, normal_map, ..." or "none".
std::string describeFeatures(FeatureSet features);

}  // namespace pt
