#pragma once
// The GPU BVH tests' scene: two triangle soups, the uniform one drawn twice and the clustered
// one once, so walks run under the TLAS; and rays through its box from every direction.
#include <string>
#include <vector>

#include "backend_hit_checks.h"
#include "render/bvh/bvh_test_util.h"
#include "support/scene_builder.h"

namespace pt::test {

inline Scene soupScene(uint32_t uniformTriangles, uint32_t clusteredTriangles) {
    Rng rng(21);
    Scene scene;
    scene.render = {32, 32, 1, 4, 0};
    const uint32_t grey = addMaterial(scene, "grey", diffuse({0.5f, 0.5f, 0.5f}));
    scene.meshes.push_back(makeSoup(SoupKind::Uniform, uniformTriangles, rng));
    scene.meshes.push_back(makeSoup(SoupKind::Clustered, clusteredTriangles, rng));
    for (uint32_t i = 0; i < 3; ++i) {
        Instance inst;
        inst.name = "soup " + std::to_string(i);
        inst.mesh = i == 2 ? 1 : 0;
        inst.materials = {grey};
        inst.objectToWorld = translationTransform(Vec3(1.7f * float(i), 0.1f * float(i), 0.0f));
        scene.instances.push_back(inst);
    }
    return scene;
}

inline std::vector<Ray> soupRays(uint32_t count, uint32_t seed) {
    return raysInBox(count, seed, Vec3(-2.0f), Vec3(5.0f, 2.0f, 2.0f));
}

}  // namespace pt::test
