#include "editor/object_edits.h"

#include <algorithm>
#include <cmath>

#include "editor/selection_box.h"
#include "render/integrator/camera.h"

namespace pt::editor {
namespace {

// Materials and textures imported by a deleted object stay in the scene (instances may share
// them, and undo needs them) but belong to no object any more: not saved.
constexpr int32_t kOrphaned = -2;

// The parts of a scene that outliner edits rearrange; meshes, materials' parameters and
// textures are untouched by them, only the object each belongs to is renumbered.
struct SceneLayout {
    std::vector<SceneObject> objects;
    std::vector<Instance> instances;
    std::vector<Light> lights;
    std::vector<int32_t> materialOwners, textureOwners;
};

SceneLayout layoutOf(const Scene& scene) {
    SceneLayout l{scene.objects, scene.instances, scene.lights, {}, {}};
    for (const NamedMaterial& m : scene.materials) l.materialOwners.push_back(m.object);
    for (const Texture& t : scene.textures) l.textureOwners.push_back(t.object);
    return l;
}

void assignLayout(Document& doc, const SceneLayout& l) {
    Scene& scene = doc.scene;
    scene.objects = l.objects;
    scene.instances = l.instances;
    scene.lights = l.lights;
    for (size_t i = 0; i < scene.materials.size() && i < l.materialOwners.size(); ++i) {
        scene.materials[i].object = l.materialOwners[i];
    }
    for (size_t i = 0; i < scene.textures.size() && i < l.textureOwners.size(); ++i) {
        scene.textures[i].object = l.textureOwners[i];
    }
}

// Owner index after removing object `removed`: later objects move down by one.
int32_t ownerAfterRemoval(int32_t owner, int32_t removed) {
    if (owner == removed) return kOrphaned;
    return owner > removed ? owner - 1 : owner;
}

std::unique_ptr<EditCommand> layoutCommand(const Document& doc, std::string label, SceneChangeMask changes,
                                           SceneLayout after) {
    return makeValueCommand<SceneLayout>(std::move(label), "", changes, layoutOf(doc.scene), std::move(after),
                                         assignLayout);
}

bool placesLights(const SceneLayout& l, int32_t object) {
    return std::any_of(l.lights.begin(), l.lights.end(), [&](const Light& x) { return x.object == object; });
}

}  // namespace

bool objectHidden(const Scene& scene, uint32_t object) {
    bool any = false;
    for (const Instance& instance : scene.instances) {
        if (instance.object != int32_t(object)) continue;
        if (instance.visible) return false;
        any = true;
    }
    return any;
}

std::unique_ptr<EditCommand> renameObject(const Document& doc, uint32_t object, const std::string& name) {
    SceneLayout after = layoutOf(doc.scene);
    const std::string old = after.objects.at(object).name;
    after.objects[object].name = name;
    // Instances named after their object follow the new name (names from the file stay).
    for (Instance& instance : after.instances) {
        if (instance.object != int32_t(object) || old.empty()) continue;
        if (instance.name == old)
            instance.name = name;
        else if (instance.name.rfind(old + ".", 0) == 0)
            instance.name = name + instance.name.substr(old.size());
    }
    return layoutCommand(doc, "Rename " + old, SceneChanges::None, std::move(after));
}

std::unique_ptr<EditCommand> setObjectHidden(const Document& doc, uint32_t object, bool hidden) {
    SceneLayout after = layoutOf(doc.scene);
    for (Instance& instance : after.instances) {
        if (instance.object == int32_t(object)) instance.visible = !hidden;
    }
    const std::string label = (hidden ? "Hide " : "Show ") + after.objects.at(object).name;
    return layoutCommand(doc, label, SceneChanges::Transforms, std::move(after));
}

std::unique_ptr<EditCommand> setObjectVariant(const Document& doc, uint32_t object, int32_t variant) {
    SceneLayout after = layoutOf(doc.scene);
    selectObjectVariant(after.objects, after.instances, object, variant);
    const SceneObject& o = after.objects.at(object);
    const std::string shown = o.variant >= 0 ? o.variants[size_t(o.variant)] : "default materials";
    // The instances' slot materials change (the instance table), and a variant may make a
    // surface emit or stop emitting (the light table).
    return layoutCommand(doc, "Variant " + shown + " of " + o.name,
                         SceneChanges::Transforms | SceneChanges::Lights, std::move(after));
}

std::unique_ptr<EditCommand> deleteObject(const Document& doc, uint32_t object) {
    const SceneLayout before = layoutOf(doc.scene);
    SceneLayout after;
    const int32_t removed = int32_t(object);
    for (size_t i = 0; i < before.objects.size(); ++i) {
        if (i != object) after.objects.push_back(before.objects[i]);
    }
    for (Instance instance : before.instances) {
        if (instance.object == removed) continue;
        if (instance.object > removed) --instance.object;
        after.instances.push_back(std::move(instance));
    }
    for (Light light : before.lights) {
        if (light.object == removed) continue;
        if (light.object > removed) --light.object;
        after.lights.push_back(std::move(light));
    }
    for (int32_t owner : before.materialOwners)
        after.materialOwners.push_back(ownerAfterRemoval(owner, removed));
    for (int32_t owner : before.textureOwners)
        after.textureOwners.push_back(ownerAfterRemoval(owner, removed));
    const SceneChangeMask changes =
        SceneChanges::Transforms |
        (placesLights(before, removed) ? SceneChanges::Lights : SceneChanges::None);
    return layoutCommand(doc, "Delete " + before.objects.at(object).name, changes, std::move(after));
}

Vec3 duplicateOffset(const Scene& scene, uint32_t object) {
    const std::optional<WorldBox> box = selectionBounds(scene, int32_t(object), -1);
    if (!box) return Vec3(0.0f);
    const RenderCamera camera = makeRenderCamera(scene.camera, 1, 1);
    const Vec3 right = normalize(camera.right), extent = box->hi - box->lo;
    const float width =
        std::fabs(right.x) * extent.x + std::fabs(right.y) * extent.y + std::fabs(right.z) * extent.z;
    // Toward the middle of the view, where there is room to see it.
    const float x = projectToImage(camera, 0.5f * (box->lo + box->hi), 1, 1, nullptr).x;
    return right * (x > 0.5f ? -1.1f * width : 1.1f * width);
}

std::unique_ptr<EditCommand> duplicateObject(const Document& doc, uint32_t object, Vec3 offset) {
    SceneLayout after = layoutOf(doc.scene);
    const int32_t source = int32_t(object);
    const int32_t copy = int32_t(after.objects.size());
    SceneObject duplicate = after.objects.at(object);
    ObjectTransform& moved = duplicate.transform;
    if (moved.useMatrix) {
        for (int axis = 0; axis < 3; ++axis) moved.matrix[12 + axis] += offset[axis];
    } else {
        moved.translate += offset;
    }
    const Affine3 shift = translationTransform(offset);
    const std::string oldName = duplicate.name;
    duplicate.name = (oldName.empty() ? std::string("object") : oldName) + " copy";
    after.objects.push_back(duplicate);
    const size_t instanceCount = after.instances.size();
    for (size_t i = 0; i < instanceCount; ++i) {
        if (after.instances[i].object != source) continue;
        Instance instance = after.instances[i];
        instance.object = copy;
        instance.name += " copy";
        instance.objectToWorld = shift * instance.objectToWorld;
        after.instances.push_back(std::move(instance));
    }
    const size_t lightCount = after.lights.size();
    for (size_t i = 0; i < lightCount; ++i) {
        if (after.lights[i].object != source) continue;
        Light light = after.lights[i];
        light.object = copy;
        light.position += offset;
        after.lights.push_back(std::move(light));
    }
    const SceneChangeMask changes =
        SceneChanges::Transforms | (placesLights(after, source) ? SceneChanges::Lights : SceneChanges::None);
    return layoutCommand(doc, "Duplicate " + oldName, changes, std::move(after));
}

std::unique_ptr<EditCommand> renameLight(const Document& doc, uint32_t light, const std::string& name) {
    SceneLayout after = layoutOf(doc.scene);
    const std::string old = after.lights.at(light).name;
    after.lights[light].name = name;
    return layoutCommand(doc, "Rename " + old, SceneChanges::None, std::move(after));
}

std::unique_ptr<EditCommand> deleteLight(const Document& doc, uint32_t light) {
    SceneLayout after = layoutOf(doc.scene);
    const std::string name = after.lights.at(light).name;
    after.lights.erase(after.lights.begin() + std::ptrdiff_t(light));
    return layoutCommand(doc, "Delete " + name, SceneChanges::Lights, std::move(after));
}

std::unique_ptr<EditCommand> duplicateLight(const Document& doc, uint32_t light) {
    SceneLayout after = layoutOf(doc.scene);
    Light copy = after.lights.at(light);
    const std::string label = "Duplicate " + copy.name;
    copy.name += " copy";
    // A copy is the scene's own light: it is saved in the JSON even when the original came
    // from a model file.
    copy.object = -1;
    after.lights.push_back(std::move(copy));
    return layoutCommand(doc, label, SceneChanges::Lights, std::move(after));
}

}  // namespace pt::editor
