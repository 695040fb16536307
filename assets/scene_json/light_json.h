#pragma once
// Punctual lights in scene JSON (the "lights" array; schema: scenes/README.md). The reader
// is strict like the rest of scene JSON: a key that does not apply to the light's type
// (a directional light's "position") is an error naming it, as is an unknown key.
#include "assets/scene_json/json_value.h"
#include "render/scene/scene.h"

namespace pt {

// Reads one "lights" element (an object); the caller adds it to the scene.
Light readLightJson(const JsonValue& value);

// The JSON object for `light`: name and type, then only the values that differ from the
// defaults and apply to the type.
Json lightToJson(const Light& light);

}  // namespace pt
