#include "assets/scene_json/material_json.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>

namespace pt {

namespace {

// A scalar or color parameter: exactly one of `scalar` and `color` is set. An angle is
// written in degrees, as every angle of scene JSON, and held in radians.
struct ParamKey {
    const char* key;
    float Material::*scalar;
    Vec3 Material::*color;
    NumberRange range;
    bool angle = false;
};

constexpr ParamKey kParamKeys[] = {
    {"baseColor", nullptr, &Material::baseColor, NumberRange::Unit},
    {"alpha", &Material::alpha, nullptr, NumberRange::Unit},
    {"metallic", &Material::metallic, nullptr, NumberRange::Unit},
    {"roughness", &Material::roughness, nullptr, NumberRange::Unit},
    {"emission", nullptr, &Material::emission, NumberRange::NonNegative},
    {"emissionStrength", &Material::emissionStrength, nullptr, NumberRange::NonNegative},
    {"ior", &Material::ior, nullptr, NumberRange::AtLeastOne},
    {"transmission", &Material::transmission, nullptr, NumberRange::Unit},
    {"specular", &Material::specular, nullptr, NumberRange::Unit},
    {"specularColor", nullptr, &Material::specularColor, NumberRange::NonNegative},
    {"clearcoat", &Material::clearcoat, nullptr, NumberRange::Unit},
    {"clearcoatRoughness", &Material::clearcoatRoughness, nullptr, NumberRange::Unit},
    {"diffuseTransmission", &Material::diffuseTransmission, nullptr, NumberRange::Unit},
    {"diffuseTransmissionColor", nullptr, &Material::diffuseTransmissionColor, NumberRange::Unit},
    {"sheenColor", nullptr, &Material::sheenColor, NumberRange::Unit},
    {"sheenRoughness", &Material::sheenRoughness, nullptr, NumberRange::Unit},
    {"anisotropyStrength", &Material::anisotropyStrength, nullptr, NumberRange::Unit},
    {"anisotropyRotation", &Material::anisotropyRotation, nullptr, NumberRange::Any, true},
    {"iridescence", &Material::iridescence, nullptr, NumberRange::Unit},
    {"iridescenceIor", &Material::iridescenceIor, nullptr, NumberRange::AtLeastOne},
    {"iridescenceThicknessMin", &Material::iridescenceThicknessMin, nullptr, NumberRange::NonNegative},
    {"iridescenceThicknessMax", &Material::iridescenceThicknessMax, nullptr, NumberRange::NonNegative},
    {"dispersion", &Material::dispersion, nullptr, NumberRange::NonNegative},
    {"thickness", &Material::thickness, nullptr, NumberRange::NonNegative},
    {"attenuationColor", nullptr, &Material::attenuationColor, NumberRange::Unit},
    // Infinity (no absorption) is the default and cannot be written in JSON: leave it out.
    {"attenuationDistance", &Material::attenuationDistance, nullptr, NumberRange::Positive},
    {"scatterColor", nullptr, &Material::scatterColor, NumberRange::Unit},
    {"scatterAnisotropy", &Material::scatterAnisotropy, nullptr, NumberRange::SignedUnit},
    {"subsurface", &Material::subsurface, nullptr, NumberRange::Unit},
    {"subsurfaceColor", nullptr, &Material::subsurfaceColor, NumberRange::Unit},
    {"subsurfaceRadius", &Material::subsurfaceRadius, nullptr, NumberRange::NonNegative},
    {"subsurfaceRadiusScale", nullptr, &Material::subsurfaceRadiusScale, NumberRange::NonNegative},
};

struct TextureKey {
    const char* key;
    TextureRef Material::*slot;
};

constexpr TextureKey kTextureKeys[] = {
    {"baseColorTexture", &Material::baseColorTexture},
    {"metallicRoughnessTexture", &Material::metallicRoughnessTexture},
    {"normalTexture", &Material::normalTexture},
    {"emissiveTexture", &Material::emissiveTexture},
    {"transmissionTexture", &Material::transmissionTexture},
    {"diffuseTransmissionTexture", &Material::diffuseTransmissionTexture},
    {"diffuseTransmissionColorTexture", &Material::diffuseTransmissionColorTexture},
    {"sheenColorTexture", &Material::sheenColorTexture},
    {"sheenRoughnessTexture", &Material::sheenRoughnessTexture},
    {"anisotropyTexture", &Material::anisotropyTexture},
    {"iridescenceTexture", &Material::iridescenceTexture},
    {"iridescenceThicknessTexture", &Material::iridescenceThicknessTexture},
};

constexpr const char* kAlphaModeNames[] = {"opaque", "mask", "blend"};

// Texture rotation is written in degrees but stored in radians. The float product below is
// the only conversion the reader makes, so the writer looks for degrees that reproduce the
// stored radians exactly, preferring the shortest decimal (30, not 29.999998); a plain
// inverse conversion could miss by an ulp.
float degreesToRadians(float degrees) { return degrees * (kPi / 180.0f); }

float radiansToDegrees(float radians) {
    const double estimate = double(radians) * (180.0 / 3.14159265358979323846);
    for (int digits = 1; digits <= 9; ++digits) {
        char text[32];
        std::snprintf(text, sizeof(text), "%.*g", digits, estimate);
        const float degrees = std::strtof(text, nullptr);
        if (sameBits(degreesToRadians(degrees), radians)) return degrees;
    }
    float degrees = float(estimate);
    for (int step = 0; step < 64 && !sameBits(degreesToRadians(degrees), radians); ++step) {
        degrees = std::nextafter(degrees, degreesToRadians(degrees) < radians ? kInf : -kInf);
    }
    return degrees;
}

Material presetMaterial(const JsonValue& type) {
    const std::string name = type.asString();
    Material m;
    if (name == "diffuse") {
        m.metallic = 0.0f;
        m.specular = 0.0f;
    } else if (name == "mirror") {
        m.metallic = 1.0f;
        m.roughness = 0.0f;
        m.baseColor = Vec3(1.0f);
    } else if (name == "glass") {
        m.transmission = 1.0f;
        m.roughness = 0.0f;
        m.metallic = 0.0f;
        m.ior = 1.5f;
    } else if (name == "subsurface") {  // wax-like: a rough dielectric over a random walk
        m.subsurface = 1.0f;
        m.roughness = 0.4f;
        m.ior = 1.4f;
    } else if (name == "fog") {  // an index-matched box of white, scattering medium
        m.transmission = 1.0f;
        m.ior = 1.0f;
        m.baseColor = Vec3(1.0f);
        m.thickness = 1.0f;
        m.attenuationDistance = 1.0f;
        m.attenuationColor = Vec3(0.5f);
        m.scatterColor = Vec3(1.0f);
    } else {
        type.fail("unknown material type \"" + name +
                  "\" (expected \"diffuse\", \"mirror\", \"glass\", \"subsurface\" or \"fog\")");
    }
    return m;
}

TextureRef readTextureSlot(const JsonValue& value, const TextureLoader& loadTexture) {
    TextureRef ref;
    if (value.json().is_string()) {
        ref.texture = loadTexture(value);
        return ref;
    }
    ObjectReader object(value);
    ref.texture = loadTexture(object.require("image"));
    if (auto offset = object.get("offset")) ref.offset = offset->asVec2();
    if (auto scale = object.get("scale")) ref.scale = scale->asVec2();
    if (auto rotation = object.get("rotation")) ref.rotation = degreesToRadians(rotation->asFloat());
    object.finish();
    return ref;
}

AlphaMode readAlphaMode(const JsonValue& value) {
    const std::string name = value.asString();
    for (uint32_t i = 0; i < 3; ++i) {
        if (name == kAlphaModeNames[i]) return AlphaMode(i);
    }
    value.fail("unknown alpha mode \"" + name + "\" (expected \"opaque\", \"mask\" or \"blend\")");
}

Json textureSlotToJson(const TextureRef& ref, const std::string& path) {
    const TextureRef defaults;
    if (sameBits(ref.offset, defaults.offset) && sameBits(ref.scale, defaults.scale) &&
        sameBits(ref.rotation, defaults.rotation)) {
        return Json(path);
    }
    Json slot = Json::object();
    slot["image"] = path;
    putIfChanged(slot, "offset", ref.offset, defaults.offset);
    putIfChanged(slot, "scale", ref.scale, defaults.scale);
    if (!sameBits(ref.rotation, defaults.rotation)) {
        slot["rotation"] = floatToJson(radiansToDegrees(ref.rotation));
    }
    return slot;
}

}  // namespace

Material readMaterialParams(ObjectReader& object, const TextureLoader& loadTexture) {
    std::optional<JsonValue> type = object.get("type");
    Material m = type ? presetMaterial(*type) : Material{};
    for (const ParamKey& param : kParamKeys) {
        if (std::optional<JsonValue> value = object.get(param.key)) {
            if (param.angle) {
                m.*param.scalar = degreesToRadians(value->asFloat(param.range));
            } else if (param.scalar) {
                m.*param.scalar = value->asFloat(param.range);
            } else {
                m.*param.color = value->asVec3(param.range);
            }
        }
    }
    if (auto mode = object.get("alphaMode")) m.alphaMode = readAlphaMode(*mode);
    if (auto cutoff = object.get("alphaCutoff")) m.alphaCutoff = cutoff->asFloat(NumberRange::Unit);
    if (auto scale = object.get("normalScale")) m.normalScale = scale->asFloat();
    if (auto sided = object.get("doubleSided")) m.doubleSided = sided->asBool() ? 1u : 0u;
    if (auto unlit = object.get("unlit")) m.unlit = unlit->asBool() ? 1u : 0u;
    for (const TextureKey& texture : kTextureKeys) {
        if (std::optional<JsonValue> value = object.get(texture.key)) {
            m.*texture.slot = readTextureSlot(*value, loadTexture);
        }
    }
    return m;
}

void writeMaterialParams(const Material& m, const TexturePathFn& texturePath, Json& out) {
    const Material defaults;
    for (const ParamKey& param : kParamKeys) {
        if (param.angle) {
            const float radians = m.*param.scalar;
            if (!sameBits(radians, defaults.*param.scalar))
                out[param.key] = floatToJson(radiansToDegrees(radians));
        } else if (param.scalar) {
            putIfChanged(out, param.key, m.*param.scalar, defaults.*param.scalar);
        }
        if (param.color) putIfChanged(out, param.key, m.*param.color, defaults.*param.color);
    }
    if (m.alphaMode != defaults.alphaMode) out["alphaMode"] = kAlphaModeNames[uint32_t(m.alphaMode) % 3];
    putIfChanged(out, "alphaCutoff", m.alphaCutoff, defaults.alphaCutoff);
    putIfChanged(out, "normalScale", m.normalScale, defaults.normalScale);
    if ((m.doubleSided != 0) != (defaults.doubleSided != 0)) out["doubleSided"] = m.doubleSided != 0;
    if (m.unlit != 0) out["unlit"] = true;
    for (const TextureKey& texture : kTextureKeys) {
        const TextureRef& ref = m.*texture.slot;
        if (ref.present()) out[texture.key] = textureSlotToJson(ref, texturePath(ref.texture, texture.key));
    }
}

Material withinFileRanges(const Material& material) {
    const Material defaults;
    Material m = material;
    const auto hold = [](float& v, float fallback, NumberRange range) {
        if (!(v == fallback)) v = nearestInRange(v, range);
    };
    for (const ParamKey& k : kParamKeys) {
        if (k.angle) {
            // Any angle, but one whose degrees a float cannot hold is taken modulo a turn.
            float& radians = m.*k.scalar;
            if (!(std::fabs(radians) < 1e30f))
                radians = std::isfinite(radians) ? std::remainder(radians, 2.0f * kPi) : 0.0f;
        } else if (k.scalar) {
            hold(m.*k.scalar, defaults.*k.scalar, k.range);
        }
        if (k.color) {
            Vec3& c = m.*k.color;
            const Vec3& d = defaults.*k.color;
            hold(c.x, d.x, k.range);
            hold(c.y, d.y, k.range);
            hold(c.z, d.z, k.range);
        }
    }
    return m;
}

bool hasDefaultParams(const Material& material) {
    const TexturePathFn anyPath = [](int32_t, const std::string&) { return std::string(); };
    Json params = Json::object();
    writeMaterialParams(material, anyPath, params);
    return params.empty();
}

}  // namespace pt
