#pragma once
// expectScenesEqual: the editor tests' check that an undo (or a save and load) gives back the
// scene exactly. Floats are compared by their bits, so a last-ulp drift (an undo that
// recomputes a transform through an inverse instead of restoring it) fails; each failure names
// the element and field. What is compared: objects, instances, materials (parameters by
// memcmp), texture owners, lights, camera, render settings, environment and mesh vertices.
#include <gtest/gtest.h>

#include <cstring>
#include <iomanip>
#include <sstream>
#include <string>
#include <vector>

#include "render/scene/scene.h"

namespace pt::test {

inline std::string floatText(float v) {
    std::ostringstream out;
    out << std::setprecision(9) << v;
    return out.str();
}

inline void expectSameBits(float a, float b, const std::string& where) {
    EXPECT_EQ(std::memcmp(&a, &b, sizeof(float)), 0)
        << where << ": " << floatText(a) << " vs " << floatText(b);
}

inline void expectSameBits(Vec3 a, Vec3 b, const std::string& where) {
    expectSameBits(a.x, b.x, where + ".x");
    expectSameBits(a.y, b.y, where + ".y");
    expectSameBits(a.z, b.z, where + ".z");
}

inline void expectSameBits(Vec4 a, Vec4 b, const std::string& where) {
    expectSameBits(a.xyz(), b.xyz(), where);
    expectSameBits(a.w, b.w, where + ".w");
}

inline void expectSameBits(const Affine3& a, const Affine3& b, const std::string& where) {
    for (int r = 0; r < 3; ++r)
        expectSameBits(a.rows[r], b.rows[r], where + ".rows[" + std::to_string(r) + "]");
}

// Element-wise, after checking the sizes; a size mismatch reports once instead of per element.
template <class T>
void expectSameBits(const std::vector<T>& a, const std::vector<T>& b, const std::string& where) {
    ASSERT_EQ(a.size(), b.size()) << where << ": sizes differ";
    for (size_t i = 0; i < a.size(); ++i) expectSameBits(a[i], b[i], where + "[" + std::to_string(i) + "]");
}

inline void expectTransformsEqual(const ObjectTransform& a, const ObjectTransform& b,
                                  const std::string& where) {
    expectSameBits(a.translate, b.translate, where + ".translate");
    expectSameBits(a.rotateDegrees, b.rotateDegrees, where + ".rotateDegrees");
    expectSameBits(a.scale, b.scale, where + ".scale");
    EXPECT_EQ(a.useMatrix, b.useMatrix) << where << ".useMatrix";
    for (int i = 0; i < 16; ++i)
        expectSameBits(a.matrix[i], b.matrix[i], where + ".matrix[" + std::to_string(i) + "]");
}

inline void expectObjectsEqual(const SceneObject& a, const SceneObject& b, const std::string& where) {
    EXPECT_EQ(a.name, b.name) << where << ".name";
    EXPECT_EQ(a.kind, b.kind) << where << ".kind";
    EXPECT_EQ(a.path, b.path) << where << ".path";
    expectTransformsEqual(a.transform, b.transform, where + ".transform");
    EXPECT_EQ(a.material, b.material) << where << ".material";
    EXPECT_EQ(a.materialOverrides, b.materialOverrides) << where << ".materialOverrides";
    EXPECT_EQ(a.variants, b.variants) << where << ".variants";
    EXPECT_EQ(a.variant, b.variant) << where << ".variant";
    EXPECT_EQ(a.morphWeights.size(), b.morphWeights.size()) << where << ".morphWeights";
    for (const auto& [mesh, weights] : a.morphWeights) {
        const auto other = b.morphWeights.find(mesh);
        if (other == b.morphWeights.end()) {
            ADD_FAILURE() << where << ".morphWeights: \"" << mesh << "\" only in the first scene";
            continue;
        }
        expectSameBits(weights, other->second, where + ".morphWeights[" + mesh + "]");
    }
}

inline void expectInstancesEqual(const Instance& a, const Instance& b, const std::string& where) {
    EXPECT_EQ(a.name, b.name) << where << ".name";
    EXPECT_EQ(a.mesh, b.mesh) << where << ".mesh";
    expectSameBits(a.objectToWorld, b.objectToWorld, where + ".objectToWorld");
    EXPECT_EQ(a.materials, b.materials) << where << ".materials";
    EXPECT_EQ(a.object, b.object) << where << ".object";
    EXPECT_EQ(a.visible, b.visible) << where << ".visible";
    EXPECT_EQ(a.variantMaterials, b.variantMaterials) << where << ".variantMaterials";
    EXPECT_EQ(a.defaultMaterials, b.defaultMaterials) << where << ".defaultMaterials";
}

inline void expectLightsEqual(const Light& a, const Light& b, const std::string& where) {
    EXPECT_EQ(a.name, b.name) << where << ".name";
    EXPECT_EQ(a.type, b.type) << where << ".type";
    expectSameBits(a.color, b.color, where + ".color");
    expectSameBits(a.intensity, b.intensity, where + ".intensity");
    expectSameBits(a.position, b.position, where + ".position");
    expectSameBits(a.direction, b.direction, where + ".direction");
    expectSameBits(a.innerConeDegrees, b.innerConeDegrees, where + ".innerConeDegrees");
    expectSameBits(a.outerConeDegrees, b.outerConeDegrees, where + ".outerConeDegrees");
    expectSameBits(a.range, b.range, where + ".range");
    EXPECT_EQ(a.object, b.object) << where << ".object";
}

inline void expectCamerasEqual(const Camera& a, const Camera& b) {
    expectSameBits(a.position, b.position, "camera.position");
    expectSameBits(a.lookAt, b.lookAt, "camera.lookAt");
    expectSameBits(a.up, b.up, "camera.up");
    expectSameBits(a.verticalFovDegrees, b.verticalFovDegrees, "camera.verticalFovDegrees");
    expectSameBits(a.apertureRadius, b.apertureRadius, "camera.apertureRadius");
    expectSameBits(a.focusDistance, b.focusDistance, "camera.focusDistance");
}

inline void expectScenesEqual(const Scene& a, const Scene& b) {
    ASSERT_EQ(a.objects.size(), b.objects.size()) << "objects";
    for (size_t i = 0; i < a.objects.size(); ++i) {
        expectObjectsEqual(a.objects[i], b.objects[i], "objects[" + std::to_string(i) + "]");
    }
    ASSERT_EQ(a.instances.size(), b.instances.size()) << "instances";
    for (size_t i = 0; i < a.instances.size(); ++i) {
        expectInstancesEqual(a.instances[i], b.instances[i], "instances[" + std::to_string(i) + "]");
    }
    ASSERT_EQ(a.materials.size(), b.materials.size()) << "materials";
    for (size_t i = 0; i < a.materials.size(); ++i) {
        const std::string where = "materials[" + std::to_string(i) + "]";
        EXPECT_EQ(a.materials[i].name, b.materials[i].name) << where << ".name";
        EXPECT_EQ(a.materials[i].object, b.materials[i].object) << where << ".object";
        EXPECT_EQ(std::memcmp(&a.materials[i].params, &b.materials[i].params, sizeof(Material)), 0)
            << where << ".params (\"" << a.materials[i].name << "\")";
    }
    ASSERT_EQ(a.textures.size(), b.textures.size()) << "textures";
    for (size_t i = 0; i < a.textures.size(); ++i) {
        EXPECT_EQ(a.textures[i].object, b.textures[i].object) << "textures[" << i << "].object";
    }
    ASSERT_EQ(a.lights.size(), b.lights.size()) << "lights";
    for (size_t i = 0; i < a.lights.size(); ++i) {
        expectLightsEqual(a.lights[i], b.lights[i], "lights[" + std::to_string(i) + "]");
    }
    expectCamerasEqual(a.camera, b.camera);
    EXPECT_EQ(a.render.width, b.render.width) << "render.width";
    EXPECT_EQ(a.render.height, b.render.height) << "render.height";
    EXPECT_EQ(a.render.maxDepth, b.render.maxDepth) << "render.maxDepth";
    EXPECT_EQ(a.render.spp, b.render.spp) << "render.spp";
    EXPECT_EQ(a.render.seed, b.render.seed) << "render.seed";
    expectSameBits(a.environment.color, b.environment.color, "environment.color");
    EXPECT_EQ(a.environment.imagePath, b.environment.imagePath) << "environment.imagePath";
    EXPECT_EQ(a.environment.texture, b.environment.texture) << "environment.texture";
    expectSameBits(a.environment.intensity, b.environment.intensity, "environment.intensity");
    expectSameBits(a.environment.rotationDegrees, b.environment.rotationDegrees,
                   "environment.rotationDegrees");
    ASSERT_EQ(a.meshes.size(), b.meshes.size()) << "meshes";
    for (size_t i = 0; i < a.meshes.size(); ++i) {
        const std::string where = "meshes[" + std::to_string(i) + "]";
        expectSameBits(a.meshes[i].positions, b.meshes[i].positions, where + ".positions");
        expectSameBits(a.meshes[i].normals, b.meshes[i].normals, where + ".normals");
    }
}

}  // namespace pt::test
