#include "render/scene/scene.h"

#include <cmath>

namespace pt {

Affine3 ObjectTransform::toAffine() const {
    if (useMatrix) {
        Affine3 m;  // column-major 4x4 as in glTF; the bottom row is dropped
        for (int r = 0; r < 3; ++r) {
            m.rows[r] = {matrix[0 + r], matrix[4 + r], matrix[8 + r], matrix[12 + r]};
        }
        return m;
    }
    const float toRadians = kPi / 180.0f;
    auto axisRotation = [](int axis, float angle) {
        const float c = std::cos(angle), s = std::sin(angle);
        Affine3 r;
        const int a = (axis + 1) % 3, b = (axis + 2) % 3;
        float m[3][3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
        m[a][a] = c;
        m[a][b] = -s;
        m[b][a] = s;
        m[b][b] = c;
        for (int i = 0; i < 3; ++i) r.rows[i] = {m[i][0], m[i][1], m[i][2], 0.0f};
        return r;
    };
    const Affine3 rotation = axisRotation(2, rotateDegrees.z * toRadians) *
                             axisRotation(1, rotateDegrees.y * toRadians) *
                             axisRotation(0, rotateDegrees.x * toRadians);
    return translationTransform(translate) * rotation * scaleTransform(scale);
}

void selectObjectVariant(std::vector<SceneObject>& objects, std::vector<Instance>& instances, uint32_t object,
                         int32_t variant) {
    SceneObject& owner = objects.at(object);
    owner.variant = variant >= 0 && size_t(variant) < owner.variants.size() ? variant : -1;
    for (Instance& instance : instances) {
        if (instance.object != int32_t(object) || instance.variantMaterials.empty()) continue;
        instance.materials = owner.variant >= 0 ? instance.variantMaterials.at(size_t(owner.variant))
                                                : instance.defaultMaterials;
    }
}

int32_t Scene::findMaterial(const std::string& name) const {
    for (size_t i = 0; i < materials.size(); ++i) {
        if (materials[i].name == name) return int32_t(i);
    }
    return -1;
}

namespace {

void growByMesh(const Mesh& mesh, const Affine3& toWorld, Vec3& lo, Vec3& hi) {
    auto grow = [&](Vec3 p) {
        lo = vmin(lo, p);
        hi = vmax(hi, p);
    };
    if (mesh.kind == GeometryKind::Spheres) {
        for (const Vec4& s : mesh.spheres) {
            for (int corner = 0; corner < 8; ++corner) {
                const Vec3 offset{corner & 1 ? s.w : -s.w, corner & 2 ? s.w : -s.w, corner & 4 ? s.w : -s.w};
                grow(toWorld.transformPoint(s.xyz() + offset));
            }
        }
        return;
    }
    for (const Vec3& p : mesh.positions) grow(toWorld.transformPoint(p));
}

}  // namespace

void Scene::worldBounds(Vec3& lo, Vec3& hi) const {
    lo = Vec3(kInf);
    hi = Vec3(-kInf);
    for (const Instance& instance : instances) {
        if (instance.visible && instance.mesh < meshes.size()) {
            growByMesh(meshes[instance.mesh], instance.objectToWorld, lo, hi);
        }
    }
    if (lo.x > hi.x) {
        lo = Vec3(-1.0f);
        hi = Vec3(1.0f);
    }
}

bool Scene::instanceBounds(uint32_t instance, Vec3& lo, Vec3& hi) const {
    lo = Vec3(kInf);
    hi = Vec3(-kInf);
    if (instance >= instances.size() || instances[instance].mesh >= meshes.size()) return false;
    growByMesh(meshes[instances[instance].mesh], instances[instance].objectToWorld, lo, hi);
    return lo.x <= hi.x;
}

uint64_t Scene::triangleCount() const {
    uint64_t count = 0;
    for (const Instance& instance : instances) {
        const Mesh& mesh = meshes[instance.mesh];
        if (instance.visible && mesh.kind == GeometryKind::Triangles) count += mesh.primitiveCount();
    }
    return count;
}

}  // namespace pt
