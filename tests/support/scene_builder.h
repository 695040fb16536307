#pragma once
// Builds small scenes in code for tests: named materials and built-in shapes with transforms.
#include <random>
#include <string>

#include "render/scene/builtin_shapes.h"
#include "render/scene/scene.h"

namespace pt::test {

// A bumpy grid of (n x n) quads over [-1, 1]^2 in the XZ plane, moved `x` along X, heights
// within +-0.05 drawn from `seed`, as one mesh.
inline Mesh bumpyGrid(uint32_t n, uint32_t seed, float x = 0.0f) {
    Mesh mesh;
    mesh.name = "grid " + std::to_string(seed);
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> height(-0.05f, 0.05f);
    for (uint32_t z = 0; z <= n; ++z) {
        for (uint32_t i = 0; i <= n; ++i) {
            mesh.positions.push_back({x + 2.0f * i / n - 1.0f, height(rng), 2.0f * z / n - 1.0f});
        }
    }
    for (uint32_t z = 0; z < n; ++z) {
        for (uint32_t i = 0; i < n; ++i) {
            const uint32_t a = z * (n + 1) + i, b = a + 1, c = a + n + 1, d = c + 1;
            mesh.indices.insert(mesh.indices.end(), {a, c, b, b, c, d});
        }
    }
    return mesh;
}

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

inline Material emitter(Vec3 radiance) {
    Material m = diffuse({0, 0, 0});
    m.emission = radiance;
    return m;
}

inline uint32_t addLight(Scene& scene, LightType type, Vec3 color, float intensity, Vec3 position,
                         Vec3 direction = {0, 0, -1}) {
    Light light;
    light.type = type;
    light.color = color;
    light.intensity = intensity;
    light.position = position;
    light.direction = direction;
    scene.lights.push_back(light);
    return uint32_t(scene.lights.size() - 1);
}

// A float RGBA image of width x height texels, filled by `texel(x, y)`.
template <class TexelFn>
inline int32_t addFloatTexture(Scene& scene, uint32_t width, uint32_t height, TexelFn texel,
                               const std::string& name = "test image") {
    Texture t;
    t.name = name;
    t.width = width;
    t.height = height;
    t.format = TexelFormat::RGBA32F;
    t.texelsF.resize(size_t(width) * height * 4);
    for (uint32_t y = 0; y < height; ++y) {
        for (uint32_t x = 0; x < width; ++x) {
            const Vec4 c = texel(x, y);
            float* out = &t.texelsF[(size_t(y) * width + x) * 4];
            out[0] = c.x;
            out[1] = c.y;
            out[2] = c.z;
            out[3] = c.w;
        }
    }
    scene.textures.push_back(std::move(t));
    return int32_t(scene.textures.size() - 1);
}

// A scene whose every pixel sees (nearly) the same point: the origin of a large diffuse floor
// facing +Y, seen from straight above through a tiny field of view. Its radiance is
// albedo / pi x irradiance, so lighting tests can compare pixels with analytic irradiance.
inline Scene floorPointScene(float albedo, uint32_t maxDepth = 1) {
    Scene scene;
    scene.render = {8, 8, maxDepth, 0, 0};
    scene.camera.position = {0, 0.5f, 0};
    scene.camera.lookAt = {0, 0, 0};
    scene.camera.up = {0, 0, -1};
    scene.camera.verticalFovDegrees = 0.01f;
    Material floor = diffuse({albedo, albedo, albedo});
    const uint32_t material = addMaterial(scene, "floor", floor);
    addShape(scene, ObjectKind::Quad, trs({0, 0, 0}, {0, 0, 0}, {100, 1, 100}), material, "floor");
    return scene;
}

// A grey ball lit by an emitting quad above it, at `size` x `size`: a small scene with direct
// and indirect light, for tests of the editor's render thread.
inline Scene ballUnderLampScene(uint32_t size = 24) {
    Scene scene;
    scene.render = {size, size, 3, 1, 0};
    scene.camera.position = {0, 0, 4};
    scene.camera.lookAt = {0, 0, 0};
    const uint32_t grey = addMaterial(scene, "grey", diffuse({0.6f, 0.6f, 0.6f}));
    const uint32_t lamp = addMaterial(scene, "lamp", emitter({3, 3, 3}));
    addShape(scene, ObjectKind::Sphere, trs({0, -0.3f, 0}, {0, 0, 0}, {0.8f, 0.8f, 0.8f}), grey, "ball");
    addShape(scene, ObjectKind::Quad, trs({0, 1.5f, 0}, {180, 0, 0}, {1, 1, 1}), lamp, "lamp");
    return scene;
}
}  // namespace pt::test
