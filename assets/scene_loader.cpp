#include "assets/scene_loader.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <map>
#include <optional>

#include "assets/file_state.h"
#include "assets/input_error.h"
#include "assets/message_text.h"
#include "assets/scene_json/scene_json.h"
#include "render/scene/scene_animation.h"

namespace pt {
namespace fs = std::filesystem;

namespace {

std::string lowerExtension(const std::string& path) {
    std::string extension = fs::path(path).extension().string();
    std::transform(extension.begin(), extension.end(), extension.begin(),
                   [](unsigned char c) { return char(std::tolower(c)); });
    return extension;
}

// Scene material index for each file material an override names, checked against the
// materials the file's placements use.
std::map<uint32_t, uint32_t> resolveOverrides(const ImportedFile& file, int32_t objectIndex,
                                              const Scene& scene) {
    std::map<uint32_t, uint32_t> remap;
    const SceneObject& object = scene.objects[size_t(objectIndex)];
    for (const auto& [fileMaterial, sceneMaterial] : object.materialOverrides) {
        const std::string where =
            "objects[" + std::to_string(objectIndex) + "].materialOverrides." + fileMaterial;
        const int32_t target = findSceneMaterial(scene, sceneMaterial);
        if (target < 0) throw InputError(where + ": unknown material \"" + sceneMaterial + "\"");
        bool found = false;
        const std::string& fileName = fileMaterial;  // a lambda may not capture a structured binding (C++17)
        const auto remapNamed = [&](const std::vector<uint32_t>& materials) {
            for (uint32_t material : materials) {
                if (scene.materials[material].name != fileName) continue;
                remap[material] = uint32_t(target);
                found = true;
            }
        };
        for (const Placement& placement : file.placements) {
            remapNamed(placement.materials);
            for (const auto& variant : placement.variantMaterials)
                remapNamed(variant);  // variants' materials too
        }
        if (!found) {
            throw InputError(where + ": " + fs::path(object.path).filename().string() +
                             " has no material \"" + fileMaterial + "\"");
        }
    }
    return remap;
}

}  // namespace

LoadResult loadScene(const std::string& path, const ProgressFn& progress) {
    LoadResult result;
    try {
        const FileState state = fileState(path);
        if (state != FileState::Readable) throw InputError(path + ": " + fileStateWords(state));
        if (lowerExtension(path) == ".json") {
            result.scene = readSceneJson(path, progress);
        } else if (isModelFile(path)) {
            result.scene = sceneFromModelFile(path, progress);
        } else {
            throw InputError(path + ": unsupported file type \"" + fs::path(path).extension().string() +
                             "\" (expected .json, .gltf, .glb or .obj)");
        }
    } catch (const InputError& e) {
        result.scene.reset();
        result.error = oneLineMessage(e.what());
    } catch (const std::exception& e) {
        // Not an input error we foresaw (e.g. out of memory): still name the file.
        result.scene.reset();
        result.error = oneLineMessage(fs::path(path).filename().string() + ": " + e.what());
    }
    return result;
}

Scene sceneFromModelFile(const std::string& path, const ProgressFn& progress) {
    reportProgress(progress, "load scene", 0.0);
    Scene scene;
    scene.sourcePath = fs::absolute(path).lexically_normal().string();
    SceneObject object;
    object.kind = ObjectKind::File;
    object.path = scene.sourcePath;
    scene.objects.push_back(object);
    const ImportedFile file = importModelFile(scene.sourcePath, 0, scene, progress);
    instantiateImportedFile(file, 0, scene);
    scene.cameraFromFile = file.camera.has_value();
    scene.camera = file.camera ? *file.camera : frameBounds(scene);
    lightUnlitModel(scene);
    reportProgress(progress, "load scene", 1.0);
    return scene;
}

bool sceneHasEmitters(const Scene& scene) {
    for (const Instance& instance : scene.instances) {
        for (uint32_t m : instance.materials) {
            if (m < scene.materials.size() && scene.materials[m].params.isEmissive()) return true;
        }
    }
    return false;
}

void lightUnlitModel(Scene& scene) {
    if (sceneHasEmitters(scene) || !scene.lights.empty() || !isBlack(scene.environment.color) ||
        scene.environment.texture >= 0) {
        return;
    }
    // A model file brings no environment; one without emitters would render black, where a
    // viewer shows it lit. Say so, since the light is not in the file.
    scene.environment.color = Vec3(1.0f);
    scene.warnings.push_back(fs::path(scene.sourcePath).filename().string() +
                             ": no lights in the file: lit by a uniform white environment of radiance 1");
}

void instantiateImportedFile(const ImportedFile& file, int32_t objectIndex, Scene& scene) {
    const std::map<uint32_t, uint32_t> remap = resolveOverrides(file, objectIndex, scene);
    SceneObject& object = scene.objects[size_t(objectIndex)];
    object.variants = file.variants;
    object.variant = -1;
    const auto placedMaterials = [&remap](const std::vector<uint32_t>& fileMaterials) {
        std::vector<uint32_t> materials;
        for (uint32_t material : fileMaterials) {
            const auto replaced = remap.find(material);
            materials.push_back(replaced == remap.end() ? material : replaced->second);
        }
        return materials;
    };
    const Affine3 objectToWorld = object.transform.toAffine();
    const std::string objectName = objectDisplayName(object);
    std::optional<AnimationRig> rig = file.rig;
    for (size_t i = 0; i < file.placements.size(); ++i) {
        const Placement& placement = file.placements[i];
        if (rig && placement.node >= 0)
            rig->instances.push_back(
                {uint32_t(placement.node), uint32_t(scene.instances.size()), placement.extra});
        Instance instance;
        instance.name = placement.name.empty() ? objectName + "." + std::to_string(i) : placement.name;
        instance.mesh = placement.mesh;
        instance.objectToWorld = objectToWorld * placement.fileToNode;
        instance.object = objectIndex;
        instance.materials = placedMaterials(placement.materials);
        for (const auto& row : placement.variantMaterials)
            instance.variantMaterials.push_back(placedMaterials(row));
        if (!instance.variantMaterials.empty()) instance.defaultMaterials = instance.materials;
        scene.instances.push_back(std::move(instance));
    }
    if (rig) {
        // Skinned meshes show their rest pose, which need not be the bind pose their vertices
        // are stored in.
        rig->object = objectIndex;
        scene.rigs.push_back(std::move(*rig));
        if (!scene.rigs.back().skinnedMeshes.empty())
            poseRig(scene, uint32_t(scene.rigs.size() - 1), -1, 0.0f);
    }
    for (const Light& fileLight : file.lights) {
        Light light = fileLight;
        light.position = objectToWorld.transformPoint(fileLight.position);
        light.direction = objectToWorld.transformVector(fileLight.direction);
        light.object = objectIndex;
        scene.lights.push_back(std::move(light));
    }
}

Camera frameBounds(const Scene& scene) {
    Vec3 lo, hi;
    scene.worldBounds(lo, hi);
    const Vec3 centre = (lo + hi) * 0.5f;
    float radius = 0.5f * length(hi - lo);
    if (!(radius > 0.0f)) radius = 1.0f;  // a single point: frame a unit sphere around it
    Camera camera;
    camera.verticalFovDegrees = 45.0f;
    // The sphere must fit the narrower of the two fields of view.
    const float aspect = float(scene.render.width) / float(std::max(scene.render.height, 1u));
    const float halfVertical = 0.5f * camera.verticalFovDegrees * kPi / 180.0f;
    const float halfHorizontal = std::atan(std::tan(halfVertical) * aspect);
    const float distance = radius / std::sin(std::min(halfVertical, halfHorizontal));
    camera.position = centre + Vec3(0.0f, 0.0f, distance);
    camera.lookAt = centre;
    camera.up = Vec3(0.0f, 1.0f, 0.0f);
    return camera;
}

Camera cameraToWorld(const Camera& camera, const Affine3& objectToWorld) {
    Camera placed = camera;
    placed.position = objectToWorld.transformPoint(camera.position);
    placed.lookAt = objectToWorld.transformPoint(camera.lookAt);
    placed.up = normalize(objectToWorld.transformVector(camera.up));
    const float before = length(camera.lookAt - camera.position);
    if (before > 0.0f) {
        const float stretch = length(placed.lookAt - placed.position) / before;
        placed.focusDistance *= stretch;
        placed.apertureRadius *= stretch;
    }
    return placed;
}

bool isModelFile(const std::string& path) {
    const std::string extension = lowerExtension(path);
    return extension == ".gltf" || extension == ".glb" || extension == ".obj";
}

int32_t findSceneMaterial(const Scene& scene, const std::string& name) {
    for (size_t i = 0; i < scene.materials.size(); ++i) {
        if (scene.materials[i].object == -1 && scene.materials[i].name == name) return int32_t(i);
    }
    return -1;
}

const char* shapeKindName(ObjectKind kind) {
    switch (kind) {
        case ObjectKind::Sphere: return "sphere";
        case ObjectKind::Box: return "box";
        case ObjectKind::Quad: return "quad";
        case ObjectKind::File: break;
    }
    return "";
}

std::string objectDisplayName(const SceneObject& object) {
    if (!object.name.empty()) return object.name;
    if (object.kind == ObjectKind::File) return fs::path(object.path).stem().string();
    return shapeKindName(object.kind);
}

}  // namespace pt
