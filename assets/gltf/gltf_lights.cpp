#include "assets/gltf/gltf_lights.h"

#include <cmath>

#include "assets/gltf/gltf_values.h"

namespace pt {
namespace {

// The light index a node's KHR_lights_punctual block names, or -1.
int nodeLight(const GltfContext& ctx, const tinygltf::Node& node, const std::string& element) {
    const auto it = node.extensions.find("KHR_lights_punctual");
    if (it == node.extensions.end()) return -1;
    const std::string where = element + ".extensions.KHR_lights_punctual";
    if (!it->second.IsObject() || !it->second.Has("light")) ctx.fail(where, "missing \"light\"");
    const tinygltf::Value& index = it->second.Get("light");
    if (!index.IsNumber()) ctx.fail(where + ".light", "expected a light index");
    const double value = index.GetNumberAsDouble();
    if (value != std::floor(value) || value < 0.0 || value > 1e9)
        ctx.fail(where + ".light", "expected a light index");
    gltfElement(ctx, ctx.model().lights, int(value), where + ".light", "light");
    return int(value);
}

Light readLight(const GltfContext& ctx, int index) {
    const tinygltf::Light& src = ctx.model().lights[size_t(index)];
    const std::string element = "KHR_lights_punctual.lights[" + std::to_string(index) + "]";
    Light light;
    light.name = src.name.empty() ? element : src.name;
    if (src.type == "point")
        light.type = LightType::Point;
    else if (src.type == "spot")
        light.type = LightType::Spot;
    else if (src.type == "directional")
        light.type = LightType::Directional;
    else
        ctx.fail(element + ".type", "'" + src.type + "' is not point, spot or directional");
    if (!src.color.empty()) {
        checkGltfNumbers(ctx, src.color, 3, element + ".color");
        for (double c : src.color) {
            if (c < 0.0) ctx.fail(element + ".color", "negative colour component");
        }
        light.color = {float(src.color[0]), float(src.color[1]), float(src.color[2])};
    }
    checkGltfNumbers(ctx, {src.intensity, src.range, src.spot.innerConeAngle, src.spot.outerConeAngle}, 4,
                     element);
    if (src.intensity < 0.0) ctx.fail(element + ".intensity", "must be >= 0");
    light.intensity = float(src.intensity);
    light.range = float(std::max(src.range, 0.0));
    if (light.type == LightType::Spot) {
        const double inner = src.spot.innerConeAngle, outer = src.spot.outerConeAngle;
        if (!(outer > 0.0 && outer <= kPi / 2 + 1e-6)) {
            ctx.fail(element + ".spot.outerConeAngle", "must be in (0, pi/2] radians");
        }
        if (!(inner >= 0.0 && inner < outer))
            ctx.fail(element + ".spot.innerConeAngle", "must be in [0, outerConeAngle)");
        light.innerConeDegrees = float(inner * 180.0 / kPi);
        light.outerConeDegrees = std::min(float(outer * 180.0 / kPi), 90.0f);
    }
    return light;
}

}  // namespace

std::vector<Light> gltfLights(const GltfContext& ctx, const std::vector<GltfNodeVisit>& visits) {
    std::vector<Light> lights;
    for (const GltfNodeVisit& visit : visits) {
        const std::string element = gltfPath("nodes", size_t(visit.node));
        const int index = nodeLight(ctx, ctx.model().nodes[size_t(visit.node)], element);
        if (index < 0) continue;
        Light light = readLight(ctx, index);
        const Vec3 direction = visit.world.transformVector({0.0f, 0.0f, -1.0f});
        if (!(lengthSquared(direction) > 0.0f) || !isFinite(direction) ||
            !isFinite(visit.world.translation())) {
            ctx.warn(element, "light transform is degenerate (zero scale); not placed");
            continue;
        }
        light.position = visit.world.translation();
        light.direction = normalize(direction);
        const std::string& nodeName = ctx.model().nodes[size_t(visit.node)].name;
        if (ctx.model().lights[size_t(index)].name.empty() && !nodeName.empty()) light.name = nodeName;
        lights.push_back(std::move(light));
    }
    return lights;
}

}  // namespace pt
