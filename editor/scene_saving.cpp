#include "editor/scene_saving.h"

#include <cstring>
#include <optional>

#include "assets/scene_json/scene_json.h"
#include "assets/scene_loader.h"

namespace pt::editor {
namespace {

bool sameParams(const Material& a, const Material& b) { return std::memcmp(&a, &b, sizeof(Material)) == 0; }

// What saving changed in the scene, to put back afterwards.
struct Adoption {
    size_t material;
    std::string name;
    int32_t object;
    std::string overrideKey;
    std::optional<std::string> previousOverride;
};

std::string uniqueMaterialName(const Scene& scene, const std::string& wanted) {
    std::string name = wanted;
    for (int n = 2; scene.findMaterial(name) >= 0; ++n) name = wanted + " " + std::to_string(n);
    return name;
}

}  // namespace

std::vector<Material> materialParams(const Scene& scene) {
    std::vector<Material> out;
    for (const NamedMaterial& m : scene.materials) out.push_back(m.params);
    return out;
}

void saveSceneJson(Scene& scene, const std::vector<Material>& importedAtLoad, const std::string& path) {
    std::vector<Adoption> adopted;
    for (size_t i = 0; i < scene.materials.size() && i < importedAtLoad.size(); ++i) {
        NamedMaterial& m = scene.materials[i];
        if (m.object < 0 || size_t(m.object) >= scene.objects.size() ||
            sameParams(m.params, importedAtLoad[i]))
            continue;
        SceneObject& object = scene.objects[size_t(m.object)];
        Adoption a{i, m.name, m.object, m.name, std::nullopt};
        if (auto it = object.materialOverrides.find(m.name); it != object.materialOverrides.end()) {
            a.previousOverride = it->second;
        }
        m.name = uniqueMaterialName(scene, objectDisplayName(object) + " " + m.name);
        m.object = -1;
        object.materialOverrides[a.overrideKey] = m.name;
        adopted.push_back(std::move(a));
    }
    auto restore = [&] {
        for (auto it = adopted.rbegin(); it != adopted.rend(); ++it) {
            NamedMaterial& m = scene.materials[it->material];
            m.name = it->name;
            m.object = it->object;
            SceneObject& object = scene.objects[size_t(it->object)];
            if (it->previousOverride)
                object.materialOverrides[it->overrideKey] = *it->previousOverride;
            else
                object.materialOverrides.erase(it->overrideKey);
        }
    };
    try {
        writeSceneJson(scene, path);
    } catch (...) {
        restore();
        throw;
    }
    restore();
}

}  // namespace pt::editor
