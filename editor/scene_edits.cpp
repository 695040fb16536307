#include "editor/scene_edits.h"

#include <filesystem>
#include <map>
#include <memory>

#include "assets/image/image_read.h"
#include "assets/scene_json/material_json.h"
#include "assets/scene_json/scene_json.h"
#include "editor/edit_labels.h"
#include "render/scene/morph.h"

namespace pt::editor {
namespace {

std::string key(const char* what, uint32_t index) { return std::string(what) + ":" + std::to_string(index); }

// An object's transform with everything it places, so that undo restores the instances and
// lights bit for bit instead of recomputing them through an inverse.
struct ObjectPlacement {
    ObjectTransform transform;
    std::vector<Affine3> instanceTransforms;  // of the object's instances, in scene order
    std::vector<Light> lights;                // the object's lights, in scene order
};

std::vector<uint32_t> instancesOf(const Scene& scene, uint32_t object) {
    std::vector<uint32_t> ids;
    for (uint32_t i = 0; i < scene.instances.size(); ++i) {
        if (scene.instances[i].object == int32_t(object)) ids.push_back(i);
    }
    return ids;
}

ObjectPlacement placementOf(const Scene& scene, uint32_t object) {
    ObjectPlacement p;
    p.transform = scene.objects.at(object).transform;
    for (const Instance& instance : scene.instances) {
        if (instance.object == int32_t(object)) p.instanceTransforms.push_back(instance.objectToWorld);
    }
    for (const Light& light : scene.lights) {
        if (light.object == int32_t(object)) p.lights.push_back(light);
    }
    return p;
}

void assignPlacement(Scene& scene, uint32_t object, const ObjectPlacement& p) {
    scene.objects.at(object).transform = p.transform;
    size_t i = 0, l = 0;
    for (Instance& instance : scene.instances) {
        if (instance.object == int32_t(object)) instance.objectToWorld = p.instanceTransforms.at(i++);
    }
    for (Light& light : scene.lights) {
        if (light.object == int32_t(object)) light = p.lights.at(l++);
    }
}

// The placement after moving the object: each instance keeps its transform relative to the
// object (the file's node hierarchy), now under the new object transform.
ObjectPlacement movedPlacement(const ObjectPlacement& before, const ObjectTransform& after) {
    const Affine3 delta = after.toAffine() * inverse(before.transform.toAffine());
    ObjectPlacement p;
    p.transform = after;
    for (const Affine3& m : before.instanceTransforms) p.instanceTransforms.push_back(delta * m);
    for (Light light : before.lights) {
        light.position = delta.transformPoint(light.position);
        light.direction = delta.transformVector(light.direction);
        p.lights.push_back(light);
    }
    return p;
}

}  // namespace

// Values typed into a field are held where the scene reader accepts them (withinFileRanges),
// so that the editor never saves a scene it cannot open.
std::unique_ptr<EditCommand> setMaterial(const Document& doc, uint32_t material, const Material& after) {
    const NamedMaterial& named = doc.scene.materials.at(material);
    return makeValueCommand<Material>(
        "Edit material " + named.name, key("material", material), materialsEdited({material}), named.params,
        withinFileRanges(after),
        [material](Document& d, const Material& m) { d.scene.materials.at(material).params = m; });
}

std::unique_ptr<EditCommand> setObjectTransform(const Document& doc, uint32_t object,
                                                const ObjectTransform& after, const std::string& verb) {
    const ObjectPlacement before = placementOf(doc.scene, object);
    // Lights placed by the object move with it: the light table follows the transform.
    SceneDelta changes = instancesMoved(instancesOf(doc.scene, object));
    if (!before.lights.empty()) changes |= SceneChanges::Lights;
    return makeValueCommand<ObjectPlacement>(
        verb + " " + doc.scene.objects.at(object).name, key("object-transform", object), changes, before,
        movedPlacement(before, after),
        [object](Document& d, const ObjectPlacement& p) { assignPlacement(d.scene, object, p); });
}

std::unique_ptr<EditCommand> setInstanceTransform(const Document& doc, uint32_t instance,
                                                  const Affine3& after, const std::string& verb) {
    const Instance& target = doc.scene.instances.at(instance);
    return makeValueCommand<Affine3>(
        verb + " " + target.name, key("instance-transform", instance), instancesMoved({instance}),
        target.objectToWorld, after,
        [instance](Document& d, const Affine3& m) { d.scene.instances.at(instance).objectToWorld = m; });
}

std::unique_ptr<EditCommand> setLight(const Document& doc, uint32_t light, const Light& after) {
    const Light& before = doc.scene.lights.at(light);
    return makeValueCommand<Light>("Edit light " + before.name, key("light", light), SceneChanges::Lights,
                                   before, after,
                                   [light](Document& d, const Light& l) { d.scene.lights.at(light) = l; });
}

std::unique_ptr<EditCommand> setCamera(const Document& doc, const Camera& after) {
    return makeValueCommand<Camera>(cameraEditLabel(doc.scene.camera, withinFileRanges(after)), "camera",
                                    SceneChanges::Camera, doc.scene.camera, withinFileRanges(after),
                                    [](Document& d, const Camera& c) { d.scene.camera = c; });
}

std::unique_ptr<EditCommand> setRenderSettings(const Document& doc, const RenderSettings& after) {
    return makeValueCommand<RenderSettings>(
        renderSettingsEditLabel(doc.scene.render, after), "render-settings", SceneChanges::Settings,
        doc.scene.render, after, [](Document& d, const RenderSettings& r) { d.scene.render = r; });
}

std::unique_ptr<EditCommand> setEnvironment(const Document& doc, const Environment& after) {
    return makeValueCommand<Environment>(environmentEditLabel(doc.scene.environment, after), "environment",
                                         SceneChanges::Environment, doc.scene.environment, after,
                                         [](Document& d, const Environment& e) { d.scene.environment = e; });
}

namespace {

class EnvironmentImageCommand final : public EditCommand {
public:
    EnvironmentImageCommand(Environment before, std::shared_ptr<const Texture> image)
        : before_(std::move(before)), image_(std::move(image)) {}
    std::string label() const override {
        return "Environment: image " + std::filesystem::path(image_->sourcePath).filename().string();
    }
    SceneDelta apply(Document& doc) override {
        std::vector<Texture>& textures = doc.scene.textures;
        SceneDelta changes = SceneChanges::Environment;
        if (index_ < 0 || size_t(index_) >= textures.size() ||
            textures[size_t(index_)].sourcePath != image_->sourcePath) {
            textures.push_back(*image_);
            index_ = int32_t(textures.size() - 1);
            changes |= SceneChanges::Textures;
        }
        Environment& e = doc.scene.environment;
        e = before_;
        e.texture = index_;
        e.imagePath = image_->sourcePath;
        return changes;
    }
    SceneDelta revert(Document& doc) override {
        doc.scene.environment = before_;
        return SceneChanges::Environment;
    }

private:
    Environment before_;
    std::shared_ptr<const Texture> image_;
    int32_t index_ = -1;  // where apply() put it in Scene::textures
};

}  // namespace

std::unique_ptr<EditCommand> setEnvironmentImage(const Document& doc, const std::string& path) {
    auto image = std::make_shared<Texture>(readTextureFile(path));
    image->sourcePath = std::filesystem::absolute(path).lexically_normal().string();
    if (image->name.empty()) image->name = std::filesystem::path(path).filename().string();
    image->object = -1;
    return std::make_unique<EnvironmentImageCommand>(doc.scene.environment, std::move(image));
}

std::unique_ptr<EditCommand> setToggles(const Document& doc, const IntegratorToggles& after) {
    return makeValueCommand<IntegratorToggles>(
        togglesEditLabel(doc.toggles, after), "toggles", SceneChanges::Settings, doc.toggles, after,
        [](Document& d, const IntegratorToggles& t) { d.toggles = t; });
}

std::unique_ptr<EditCommand> setViewer(const Document& doc, const ViewerSettings& after) {
    return makeValueCommand<ViewerSettings>(viewerEditLabel(doc.viewer, after), "viewer",
                                            SceneChanges::Display, doc.viewer, after,
                                            [](Document& d, const ViewerSettings& v) { d.viewer = v; });
}

std::unique_ptr<EditCommand> setColorSettings(const Document& doc, const ColorSettings& after) {
    return makeValueCommand<ColorSettings>("Color view", "color", SceneChanges::Display, doc.scene.color,
                                           after,
                                           [](Document& d, const ColorSettings& c) { d.scene.color = c; });
}

std::unique_ptr<EditCommand> setMorphWeights(const Document& doc, uint32_t mesh,
                                             const std::vector<float>& after) {
    // The weights, and what each object records of them for saving, before and after.
    struct MorphState {
        std::vector<float> weights;
        std::vector<std::map<std::string, std::vector<float>>> objectWeights;  // per scene object
    };
    const Scene& scene = doc.scene;
    const Mesh& target = scene.meshes.at(mesh);
    MorphState before{target.morphWeights, {}};
    for (const SceneObject& object : scene.objects) before.objectWeights.push_back(object.morphWeights);
    MorphState next{after, before.objectWeights};
    for (const Instance& instance : scene.instances) {
        if (instance.mesh == mesh && instance.object >= 0)
            next.objectWeights.at(size_t(instance.object))[target.name] = after;
    }
    auto assign = [mesh](Document& d, const MorphState& state) {
        Mesh& m = d.scene.meshes.at(mesh);
        m.morphWeights = state.weights;
        applyMorphWeights(m);
        for (size_t i = 0; i < d.scene.objects.size() && i < state.objectWeights.size(); ++i) {
            d.scene.objects[i].morphWeights = state.objectWeights[i];
        }
    };
    return makeValueCommand<MorphState>("Morph " + target.name, key("morph", mesh), meshesMoved({mesh}),
                                        before, next, assign);
}

}  // namespace pt::editor
