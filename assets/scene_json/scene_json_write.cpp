// Writing scene JSON (schema: scenes/README.md). Only values that differ from their defaults
// are written, paths are relative to the output file, keys come in a fixed order and floats
// in their shortest exact form, so the same scene always gives the same text and reads back
// bit-identical.
#include <algorithm>
#include <filesystem>

#include "assets/atomic_file.h"
#include "assets/input_error.h"
#include "assets/scene_json/json_value.h"
#include "assets/scene_json/light_json.h"
#include "assets/scene_json/material_json.h"
#include "assets/scene_json/scene_json.h"
#include "assets/scene_loader.h"

namespace pt {
namespace fs = std::filesystem;

namespace {

// Lexical, so that the output does not depend on symlinks or on what exists on disk; a
// path on another root (no relative form) stays absolute.
std::string relativePath(const std::string& path, const fs::path& folder) {
    const fs::path absolute = fs::absolute(path).lexically_normal();
    const fs::path relative = absolute.lexically_relative(folder);
    return relative.empty() ? absolute.generic_string() : relative.generic_string();
}

bool sameCamera(const Camera& a, const Camera& b) {
    return sameBits(a.position, b.position) && sameBits(a.lookAt, b.lookAt) && sameBits(a.up, b.up) &&
           sameBits(a.verticalFovDegrees, b.verticalFovDegrees) &&
           sameBits(a.apertureRadius, b.apertureRadius) && sameBits(a.focusDistance, b.focusDistance);
}

Json cameraToJson(const Camera& camera) {
    const Camera defaults;
    Json out = Json::object();  // written even when empty: "camera": {} is the default camera
    putIfChanged(out, "position", camera.position, defaults.position);
    putIfChanged(out, "lookAt", camera.lookAt, defaults.lookAt);
    putIfChanged(out, "up", camera.up, defaults.up);
    putIfChanged(out, "fov", camera.verticalFovDegrees, defaults.verticalFovDegrees);
    putIfChanged(out, "aperture", camera.apertureRadius, defaults.apertureRadius);
    putIfChanged(out, "focusDistance", camera.focusDistance, defaults.focusDistance);
    return out;
}

Json renderToJson(const RenderSettings& render) {
    const RenderSettings defaults;
    Json out = Json::object();
    if (render.width != defaults.width || render.height != defaults.height) {
        out["resolution"] = Json::array({render.width, render.height});
    }
    if (render.maxDepth != defaults.maxDepth) out["maxDepth"] = render.maxDepth;
    if (render.spp != defaults.spp) out["spp"] = render.spp;
    if (render.seed != defaults.seed) out["seed"] = render.seed;
    return out;
}

Json environmentToJson(const Environment& environment, const fs::path& folder) {
    const Environment defaults;
    Json out = Json::object();
    putIfChanged(out, "color", environment.color, defaults.color);
    if (!environment.imagePath.empty()) out["image"] = relativePath(environment.imagePath, folder);
    putIfChanged(out, "intensity", environment.intensity, defaults.intensity);
    putIfChanged(out, "rotation", environment.rotationDegrees, defaults.rotationDegrees);
    return out;
}

Json colorToJson(const ColorSettings& color, const fs::path& folder) {
    Json out = Json::object();
    if (!color.config.empty()) out["config"] = relativePath(color.config, folder);
    const std::pair<const char*, const std::string*> names[] = {
        {"display", &color.display}, {"view", &color.view}, {"look", &color.look}};
    for (const auto& [key, name] : names) {
        if (!name->empty()) out[key] = *name;
    }
    return out;
}

Json transformToJson(const ObjectTransform& transform) {
    const ObjectTransform defaults;
    Json out = Json::object();
    if (transform.useMatrix) {
        out["matrix"] = Json::array();
        for (float element : transform.matrix) out["matrix"].push_back(floatToJson(element));
        return out;
    }
    putIfChanged(out, "translate", transform.translate, defaults.translate);
    putIfChanged(out, "rotate", transform.rotateDegrees, defaults.rotateDegrees);
    const Vec3 s = transform.scale;
    if (!sameBits(s, defaults.scale)) {
        out["scale"] = sameBits(s.x, s.y) && sameBits(s.x, s.z) ? floatToJson(s.x) : vec3ToJson(s);
    }
    return out;
}

// Whether `weights` are the file's own for the object's meshes named `mesh` (those its
// instances use): the editor records every weight change on the object, and a change back to
// the file's pose need not be saved. A mesh no instance uses is not known here: written.
bool isFileMorphPose(const Scene& scene, size_t objectIndex, const std::string& mesh,
                     const std::vector<float>& weights) {
    bool found = false;
    for (const Instance& instance : scene.instances) {
        if (instance.object != int32_t(objectIndex) || instance.mesh >= scene.meshes.size()) continue;
        const Mesh& used = scene.meshes[instance.mesh];
        if (used.name != mesh) continue;
        const std::vector<float>& defaults = used.defaultMorphWeights;
        if (defaults.size() != weights.size() ||
            !std::equal(defaults.begin(), defaults.end(), weights.begin(),
                        [](float a, float b) { return sameBits(a, b); })) {
            return false;
        }
        found = true;
    }
    return found;
}

Json morphWeightsToJson(const Scene& scene, size_t objectIndex) {
    Json out = Json::object();
    for (const auto& [mesh, weights] : scene.objects[objectIndex].morphWeights) {
        if (isFileMorphPose(scene, objectIndex, mesh, weights)) continue;
        Json list = Json::array();
        for (float weight : weights) list.push_back(floatToJson(weight));
        out[mesh] = std::move(list);
    }
    return out;
}

Json objectToJson(const Scene& scene, size_t objectIndex, const fs::path& folder) {
    const SceneObject& object = scene.objects[objectIndex];
    Json out = Json::object();
    if (!object.name.empty()) out["name"] = object.name;
    if (object.kind == ObjectKind::File) {
        out["file"] = relativePath(object.path, folder);
    } else {
        out["shape"] = shapeKindName(object.kind);
    }
    if (object.kind != ObjectKind::File && !object.material.empty() &&
        object.material != kDefaultMaterialName) {
        out["material"] = object.material;
    }
    if (object.kind == ObjectKind::File && !object.materialOverrides.empty()) {
        out["materialOverrides"] = Json::object();
        for (const auto& [from, to] : object.materialOverrides) out["materialOverrides"][from] = to;
    }
    if (object.kind == ObjectKind::File) {
        Json morphWeights = morphWeightsToJson(scene, objectIndex);
        if (!morphWeights.empty()) out["morphWeights"] = std::move(morphWeights);
    }
    if (object.variant >= 0 && size_t(object.variant) < object.variants.size()) {
        out["variant"] = object.variants[size_t(object.variant)];
    }
    if (object.kind == ObjectKind::File && !object.animation.empty()) {
        out["animation"] = {{"name", object.animation}, {"time", floatToJson(object.animationTime)}};
    }
    Json transform = transformToJson(object.transform);
    if (!transform.empty()) out["transform"] = std::move(transform);
    return out;
}

// The loader adds the default material itself when a shape names none, right after the
// JSON's own materials; writing it would be noise. Left out only where the loader puts it
// back unchanged at the same index: last of the scene's materials, default parameters, and
// used by a shape that will name no material.
bool isImplicitDefault(const Scene& scene, size_t index) {
    const NamedMaterial& material = scene.materials[index];
    if (material.name != kDefaultMaterialName || material.object != -1) return false;
    const auto later =
        std::find_if(scene.materials.begin() + std::ptrdiff_t(index) + 1, scene.materials.end(),
                     [](const NamedMaterial& m) { return m.object == -1; });
    if (later != scene.materials.end()) return false;
    const bool usedByShape =
        std::any_of(scene.objects.begin(), scene.objects.end(), [](const SceneObject& o) {
            return o.kind != ObjectKind::File && (o.material.empty() || o.material == kDefaultMaterialName);
        });
    return hasDefaultParams(material.params) && usedByShape;
}

Json materialsToJson(const Scene& scene, const fs::path& folder, const std::string& outputName) {
    Json out = Json::array();
    for (size_t i = 0; i < scene.materials.size(); ++i) {
        const NamedMaterial& material = scene.materials[i];
        if (material.object != -1 || isImplicitDefault(scene, i)) continue;
        const std::string where = outputName + ": materials[" + std::to_string(out.size()) + "].";
        auto texturePath = [&](int32_t texture, const std::string& slot) {
            const Texture& image = scene.textures.at(size_t(texture));
            if (image.sourcePath.empty()) {
                throw InputError(where + slot + ": texture \"" + image.name +
                                 "\" is embedded in a model file; scene JSON can only name image files");
            }
            return relativePath(image.sourcePath, folder);
        };
        Json entry = Json::object();
        entry["name"] = material.name;
        writeMaterialParams(material.params, texturePath, entry);
        out.push_back(std::move(entry));
    }
    return out;
}

// The lights the JSON defines; those of model files come back with their files.
Json lightsToJson(const Scene& scene) {
    Json out = Json::array();
    for (const Light& light : scene.lights) {
        if (light.object == -1) out.push_back(lightToJson(light));
    }
    return out;
}

}  // namespace

std::string sceneToJson(const Scene& scene, const std::string& outputPath) {
    const fs::path folder = fs::absolute(outputPath).lexically_normal().parent_path();
    Json root = Json::object();
    root["version"] = kSceneJsonVersion;
    // A camera the loader would compute again (framing the bounds) is left out; any other,
    // including one taken from a model file, is written.
    if (scene.cameraFromFile || !sameCamera(scene.camera, frameBounds(scene))) {
        root["camera"] = cameraToJson(scene.camera);
    }
    const std::pair<const char*, Json> sections[] = {
        {"render", renderToJson(scene.render)},
        {"environment", environmentToJson(scene.environment, folder)},
        {"color", colorToJson(scene.color, folder)},
        {"materials", materialsToJson(scene, folder, fs::path(outputPath).filename().string())},
        {"lights", lightsToJson(scene)},
    };
    for (const auto& [key, value] : sections) {
        if (!value.empty()) root[key] = value;
    }
    Json objects = Json::array();
    for (size_t i = 0; i < scene.objects.size(); ++i) objects.push_back(objectToJson(scene, i, folder));
    if (!objects.empty()) root["objects"] = std::move(objects);
    try {
        return prettyJson(root);
    } catch (const Json::exception& e) {  // e.g. a name that is not valid UTF-8
        throw InputError(fs::path(outputPath).filename().string() + ": " + e.what());
    }
}

void writeSceneJson(const Scene& scene, const std::string& path) {
    writeTextAtomically(path, sceneToJson(scene, path));
}

}  // namespace pt
