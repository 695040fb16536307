#pragma once
// Material parameters in scene JSON. One table of keys serves the reader and the writer, so
// the two cannot drift apart; the defaults are Material{}'s (render/kernel/material.h).
#include <cstdint>
#include <functional>
#include <string>

#include "assets/scene_json/json_value.h"
#include "render/kernel/material.h"

namespace pt {

// Turns a texture slot's image path (the JSON string at `image`, relative to the JSON file)
// into a Scene::textures index, loading the image on first use; fails naming `image`.
using TextureLoader = std::function<int32_t(const JsonValue& image)>;
// The image path to write for a Scene::textures index; `slot` names the key for messages.
using TexturePathFn = std::function<std::string(int32_t texture, const std::string& slot)>;

// Reads the optional preset ("type": "diffuse" | "mirror" | "glass"), then every parameter
// key, explicit keys overriding the preset. The caller reads "name" and calls finish().
Material readMaterialParams(ObjectReader& object, const TextureLoader& loadTexture);

// Adds to `out` every parameter that differs from Material{}, as expanded keys (a preset is
// never written), in the schema's order.
void writeMaterialParams(const Material& material, const TexturePathFn& texturePath, Json& out);

// The material with every parameter the reader checks held in its range (nearestInRange), so
// that a saved scene reopens; a parameter at its default is kept (attenuationDistance's
// infinity, which the writer leaves out).
Material withinFileRanges(const Material& material);

// True when writeMaterialParams would write nothing: every parameter is Material{}'s.
bool hasDefaultParams(const Material& material);

}  // namespace pt
