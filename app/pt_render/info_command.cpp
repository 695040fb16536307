// pt-render info: what a scene holds and what it costs to load and build.
#include <cstdio>
#include <nlohmann/json.hpp>

#include "assets/scene_loader.h"
#include "cli/cli_options.h"
#include "cli/scene_input.h"
#include "pt_render/commands.h"
#include "render/compile/compile_scene.h"
#include "render/compile/scene_features.h"

namespace pt::cli {

namespace {

nlohmann::ordered_json describe(const Scene& scene, const CompiledScene& compiled, double loadSeconds) {
    Vec3 lo, hi;
    scene.worldBounds(lo, hi);
    const CompileStats& s = compiled.stats;
    nlohmann::ordered_json j;
    j["scene"] = scene.sourcePath;
    j["triangles"] = s.instancedTriangles;
    j["unique_triangles"] = s.meshTriangles;
    j["spheres"] = s.spheres;
    j["meshes"] = scene.meshes.size();
    j["instances"] = s.instanceCount;
    j["materials"] = scene.materials.size();
    j["textures"] = scene.textures.size();
    j["emissive_triangles"] = s.emitterCount;
    j["sphere_lights"] = s.sphereLightCount;
    j["punctual_lights"] = s.punctualLightCount;
    j["environment"] = scene.environment.texture >= 0 ? "image" : "color";
    // glTF KHR_materials_variants, per object that has them: {"chair": ["Red", "Blue"]}.
    nlohmann::ordered_json variants = nlohmann::ordered_json::object();
    for (const SceneObject& object : scene.objects) {
        if (!object.variants.empty()) variants[objectDisplayName(object)] = object.variants;
    }
    if (!variants.empty()) j["material_variants"] = std::move(variants);
    // glTF extensions the model files use: {"KHR_draco_mesh_compression": "honoured", ...}.
    nlohmann::ordered_json extensions = nlohmann::ordered_json::object();
    for (const auto& [name, honoured] : scene.gltfExtensions)
        extensions[name] = honoured ? "honoured" : "ignored";
    if (!extensions.empty()) j["gltf_extensions"] = std::move(extensions);
    // What the scene uses (scene_features.h); the CUDA backend picks its kernel variant by it.
    j["features"] = featureNames(compiled.features);
    j["bounds"] = {{"min", {lo.x, lo.y, lo.z}}, {"max", {hi.x, hi.y, hi.z}}};
    j["load_seconds"] = loadSeconds;
    j["blas_build_seconds"] = s.blasSeconds;
    j["tlas_build_seconds"] = s.tlasSeconds;
    j["blas_nodes"] = s.blasNodes;
    j["warnings"] = scene.warnings.size();
    return j;
}

// "KHR_materials_variants, KHR_texture_transform; ignored: EXT_lights_image_based".
std::string extensionsText(const nlohmann::ordered_json& extensions) {
    std::string honoured, ignored;
    for (const auto& [name, state] : extensions.items()) {
        std::string& list = state == "honoured" ? honoured : ignored;
        list += (list.empty() ? "" : ", ") + name;
    }
    return honoured +
           (ignored.empty() ? "" : (honoured.empty() ? "" : "; ") + std::string("ignored: ") + ignored);
}

}  // namespace

int runInfo(const std::vector<std::string>& args) {
    const Options o(args, {}, {"--json", "--quiet"});
    if (o.positional().size() != 1) throw UsageError("expected one SCENE argument");
    ProgressBar bar(!o.has("--quiet") && !o.has("--json"));
    const SceneInput input = loadSceneInput(o.positional()[0], bar);
    const CompiledScene compiled = compileRenderScene(input.scene, {}, bar.callback());
    bar.finish();
    const nlohmann::ordered_json j = describe(input.scene, compiled, input.loadSeconds);
    if (o.has("--json")) {
        std::printf("%s\n", j.dump(2).c_str());
        return 0;
    }
    for (const auto& [key, value] : j.items()) {
        const std::string text = key == "features"          ? describeFeatures(compiled.features)
                                 : key == "gltf_extensions" ? extensionsText(value)
                                 : value.is_string()        ? value.get<std::string>()
                                                            : value.dump();
        std::printf("%-20s %s\n", key.c_str(), text.c_str());
    }
    return 0;
}

}  // namespace pt::cli
