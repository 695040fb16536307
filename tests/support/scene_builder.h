#pragma once
// Builds small scenes in code for tests: named materials and built-in shapes with transforms.
#include <string>

#include "render/scene/builtin_shapes.h"
#include "render/scene/scene.h"

namespace pt::test {

inline uint32_t addMaterial(Scene& scene, const std::string& name, const Material& m) {
    scene.materials.push_back({name, m, -1});
    return uint32_t(scene.materials.size() - 1);
}

inline Material diffuse(Vec3 albedo) {
    Material m;
    m.baseColor = albedo;
    m.metallic = 0.0f;
    m.specular = 0.0f;
    return m;
}

inline uint32_t addShape(Scene& scene, ObjectKind kind, const ObjectTransform& transform, uint32_t material,
                         const std::string& name = "") {
    SceneObject object;
    object.name = name;
    object.kind = kind;
    object.transform = transform;
    object.material = scene.materials[material].name;
    scene.objects.push_back(object);
    Instance instance;
    instance.name = name;
    instance.mesh = builtinShapeMesh(scene, kind);
    instance.objectToWorld = transform.toAffine();
    instance.materials = {material};
    instance.object = int32_t(scene.objects.size() - 1);
    scene.instances.push_back(instance);
    return uint32_t(scene.instances.size() - 1);
}

inline ObjectTransform trs(Vec3 translate, Vec3 rotateDegrees = {0, 0, 0}, Vec3 scale = {1, 1, 1}) {
    ObjectTransform t;
    t.translate = translate;
    t.rotateDegrees = rotateDegrees;
    t.scale = scale;
    return t;
}

}  // namespace pt::test
