#include "assets/scene_json/light_json.h"

#include <iterator>

namespace pt {

namespace {

constexpr const char* kTypeNames[] = {"point", "spot", "directional"};

const char* typeName(LightType type) { return kTypeNames[uint32_t(type)]; }

LightType readType(const JsonValue& value) {
    const std::string name = value.asString();
    for (uint32_t i = 0; i < std::size(kTypeNames); ++i) {
        if (name == kTypeNames[i]) return LightType(i);
    }
    value.fail("unknown light type \"" + name + "\" (expected \"point\", \"spot\" or \"directional\")");
}

// Fails when `key` was given for a type it does not apply to.
void requireApplies(const std::optional<JsonValue>& key, bool applies, LightType type, const char* why) {
    if (key && !applies) key->fail(std::string("a ") + typeName(type) + " light " + why);
}

}  // namespace

Light readLightJson(const JsonValue& value) {
    ObjectReader reader(value);
    Light light;
    if (auto name = reader.get("name")) light.name = name->asString();
    light.type = readType(reader.require("type"));
    if (auto color = reader.get("color")) light.color = color->asVec3(NumberRange::NonNegative);
    if (auto intensity = reader.get("intensity"))
        light.intensity = intensity->asFloat(NumberRange::NonNegative);
    const std::optional<JsonValue> position = reader.get("position");
    const std::optional<JsonValue> direction = reader.get("direction");
    const std::optional<JsonValue> inner = reader.get("innerConeAngle");
    const std::optional<JsonValue> outer = reader.get("outerConeAngle");
    reader.finish();
    const LightType type = light.type;
    requireApplies(position, type != LightType::Directional, type,
                   "has no position (it is infinitely far away)");
    requireApplies(direction, type != LightType::Point, type,
                   "shines in every direction; it takes no direction");
    requireApplies(inner, type == LightType::Spot, type, "has no cone");
    requireApplies(outer, type == LightType::Spot, type, "has no cone");
    if (position) light.position = position->asVec3();
    if (direction) {
        light.direction = direction->asVec3();
        if (lengthSquared(light.direction) == 0.0f) direction->fail("the direction is zero");
    }
    if (outer) {
        light.outerConeDegrees = outer->asFloat();
        if (!(light.outerConeDegrees > 0.0f && light.outerConeDegrees <= 90.0f)) {
            outer->fail("expected degrees in (0, 90], got " + outer->describe());
        }
    }
    if (inner) {
        light.innerConeDegrees = inner->asFloat();
        if (!(light.innerConeDegrees >= 0.0f && light.innerConeDegrees < light.outerConeDegrees)) {
            inner->fail("expected degrees in [0, outerConeAngle), got " + inner->describe());
        }
    }
    return light;
}

Json lightToJson(const Light& light) {
    const Light defaults;
    Json out = Json::object();
    if (!light.name.empty()) out["name"] = light.name;
    out["type"] = typeName(light.type);
    putIfChanged(out, "color", light.color, defaults.color);
    putIfChanged(out, "intensity", light.intensity, defaults.intensity);
    if (light.type != LightType::Directional)
        putIfChanged(out, "position", light.position, defaults.position);
    if (light.type != LightType::Point) putIfChanged(out, "direction", light.direction, defaults.direction);
    if (light.type == LightType::Spot) {
        putIfChanged(out, "innerConeAngle", light.innerConeDegrees, defaults.innerConeDegrees);
        putIfChanged(out, "outerConeAngle", light.outerConeDegrees, defaults.outerConeDegrees);
    }
    return out;
}

}  // namespace pt
