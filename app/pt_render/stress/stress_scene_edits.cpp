#include "pt_render/stress/stress_scene_edits.h"

#include <cmath>
#include <stdexcept>

#include "pt_render/gen/gen_random.h"

namespace pt::cli {

void scaleAndMoveScene(Scene& scene, float scale, Vec3 offset) {
    Affine3 transform;
    for (int r = 0; r < 3; ++r)
        transform.rows[r] = {r == 0 ? scale : 0.0f, r == 1 ? scale : 0.0f, r == 2 ? scale : 0.0f, 0.0f};
    transform.rows[0].w = offset.x, transform.rows[1].w = offset.y, transform.rows[2].w = offset.z;
    for (Instance& instance : scene.instances) instance.objectToWorld = transform * instance.objectToWorld;
    for (Light& light : scene.lights) light.position = transform.transformPoint(light.position);
    Camera& camera = scene.camera;
    camera.position = transform.transformPoint(camera.position);
    camera.lookAt = transform.transformPoint(camera.lookAt);
    camera.apertureRadius *= scale;
    camera.focusDistance *= scale;
}

void roundAsIfMoved(Scene& scene, Vec3 offset) {
    scaleAndMoveScene(scene, 1.0f, offset);
    scaleAndMoveScene(scene, 1.0f, -offset);
}

void addTriangleSoup(Scene& scene, uint32_t count, Vec3 center, float side, const std::string& material) {
    const int32_t materialIndex = scene.findMaterial(material);
    if (materialIndex < 0) throw std::invalid_argument("addTriangleSoup: no material " + material);
    GenRandom random(count);
    Mesh mesh;
    mesh.name = "triangle soup";
    mesh.positions.reserve(size_t(count) * 3);
    mesh.indices.reserve(size_t(count) * 3);
    const auto coordinate = [&](float c) { return float(c + side * (random.uniform() - 0.5)); };
    for (uint32_t i = 0; i < count * 3; ++i) {
        mesh.positions.push_back({coordinate(center.x), coordinate(center.y), coordinate(center.z)});
        mesh.indices.push_back(i);
    }
    scene.meshes.push_back(std::move(mesh));
    Instance instance;
    instance.name = "triangle soup";
    instance.mesh = uint32_t(scene.meshes.size() - 1);
    instance.materials = {uint32_t(materialIndex)};
    scene.instances.push_back(std::move(instance));
}

void setSunEnvironment(Scene& scene, const SunEnvironment& e) {
    Texture texture;
    texture.name = "sun environment";
    texture.width = e.width;
    texture.height = e.height;
    texture.format = TexelFormat::RGBA32F;
    texture.texelsF.assign(size_t(e.width) * e.height * 4, e.sky);
    for (size_t i = 3; i < texture.texelsF.size(); i += 4) texture.texelsF[i] = 1.0f;
    float* sun = &texture.texelsF[(size_t(e.sunRow) * e.width + e.sunColumn) * 4];
    sun[0] = sun[1] = sun[2] = e.sun;
    scene.textures.push_back(std::move(texture));
    scene.environment.texture = int32_t(scene.textures.size() - 1);
    scene.environment.intensity = 1.0f;
    scene.environment.color = {0.0f, 0.0f, 0.0f};
}

double floorRadianceUnder(const SunEnvironment& e) {
    const double pi = 3.14159265358979323846;
    const double theta = (e.sunRow + 0.5) / e.height * pi;
    const double solidAngle = 2.0 * pi * pi * std::sin(theta) / (double(e.width) * e.height);
    const double irradiance = pi * e.sky + (e.sun - e.sky) * std::cos(theta) * solidAngle;
    return irradiance / pi;
}

}  // namespace pt::cli
