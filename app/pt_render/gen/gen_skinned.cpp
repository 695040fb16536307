#include "pt_render/gen/gen_skinned.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>

#include "pt_render/gen/gen_sphere.h"
#include "render/math/affine.h"

namespace pt::cli {

namespace {

constexpr double kPi = 3.14159265358979323846;

Vec4 turnAboutZ(float radians) { return {0.0f, 0.0f, std::sin(0.5f * radians), std::cos(0.5f * radians)}; }

std::array<float, 16> columnMajor(const Affine3& m) {
    std::array<float, 16> out{};
    for (int c = 0; c < 4; ++c) {
        for (int r = 0; r < 3; ++r) out[size_t(4 * c + r)] = m.at(r, c);
        out[size_t(4 * c + 3)] = c == 3 ? 1.0f : 0.0f;
    }
    return out;
}

// Stretches the sphere along Y into the column; normals follow by the inverse transpose.
void stretch(Mesh& mesh, float factor) {
    tbb::parallel_for(tbb::blocked_range<size_t>(0, mesh.positions.size(), 8192),
                      [&](const tbb::blocked_range<size_t>& range) {
                          for (size_t v = range.begin(); v != range.end(); ++v) {
                              mesh.positions[v].y *= factor;
                              Vec3& n = mesh.normals[v];
                              n = normalize(Vec3(n.x, n.y / factor, n.z));
                          }
                      });
}

// Each vertex on the two joints of the chain segment its height falls in, blended smoothly
// across the segment (a smoothstep), so the column bends without creases.
void weighVertices(const Mesh& mesh, uint32_t joints, GenSkin& skin) {
    const size_t n = mesh.positions.size();
    skin.vertexJoints.resize(n);
    skin.vertexWeights.resize(n);
    const float segments = float(joints - 1);
    tbb::parallel_for(tbb::blocked_range<size_t>(0, n, 8192), [&](const tbb::blocked_range<size_t>& range) {
        for (size_t v = range.begin(); v != range.end(); ++v) {
            const float along = (mesh.positions[v].y + kSkinnedColumnHalfHeight) /
                                (2.0f * kSkinnedColumnHalfHeight) * segments;
            const float clamped = std::clamp(along, 0.0f, segments);
            const uint32_t k = std::min(uint32_t(clamped), joints - 2);
            const float f = clamped - float(k), smooth = f * f * (3.0f - 2.0f * f);
            skin.vertexJoints[v] = {uint16_t(k), uint16_t(k + 1), 0, 0};
            skin.vertexWeights[v] = {1.0f - smooth, smooth, 0.0f, 0.0f};
        }
    });
}

}  // namespace

GenScene generateSkinnedColumn(const SkinnedSpec& spec, const ProgressFn& progress) {
    GenScene scene;
    scene.mesh = generateDisplacedSphere({spec.targetTriangles, spec.amplitude, spec.seed}, progress);
    scene.mesh.name = "skinned column";
    stretch(scene.mesh, kSkinnedColumnHalfHeight);
    scene.instances.push_back(GenNode{});

    GenSkin skin;
    const float spacing = 2.0f * kSkinnedColumnHalfHeight / float(spec.joints - 1);
    Affine3 global;
    for (uint32_t j = 0; j < spec.joints; ++j) {
        GenNode joint;
        joint.translation = j == 0 ? Vec3(0.0f, -kSkinnedColumnHalfHeight, 0.0f) : Vec3(0.0f, spacing, 0.0f);
        skin.joints.push_back(joint);
        global = global * translationTransform(joint.translation);
        skin.inverseBindMatrices.push_back(columnMajor(inverse(global)));
    }
    weighVertices(scene.mesh, spec.joints, skin);
    skin.animation = "sway";
    for (uint32_t k = 0; k <= spec.keysPerPeriod; ++k)
        skin.keyTimes.push_back(spec.periodSeconds * float(k) / float(spec.keysPerPeriod));
    for (uint32_t j = 1; j < spec.joints; ++j) {
        std::vector<Vec4> rotations;
        for (const float t : skin.keyTimes) {
            const double phase = 2.0 * kPi * double(t / spec.periodSeconds) + 0.7 * double(j);
            rotations.push_back(turnAboutZ(spec.swayRadians * float(std::sin(phase))));
        }
        skin.keyRotations.push_back(std::move(rotations));
    }
    scene.skin = std::move(skin);

    // Frame the joints' sweep over every key, widened by the column's radius.
    const float radius = float(1.0 + spec.amplitude);
    float reach = 0.0f, top = kSkinnedColumnHalfHeight;
    for (size_t key = 0; key < scene.skin->keyTimes.size(); ++key) {
        Affine3 joint = translationTransform(scene.skin->joints[0].translation);
        for (uint32_t j = 1; j < spec.joints; ++j) {
            joint = joint * translationTransform(scene.skin->joints[j].translation) *
                    rotationTransform(scene.skin->keyRotations[j - 1][key]);
            reach = std::max(reach, std::fabs(joint.translation().x));
            top = std::max(top, joint.translation().y);
        }
    }
    scene.camera = frameBox(Vec3(-reach - radius, -kSkinnedColumnHalfHeight - radius, -radius),
                            Vec3(reach + radius, top + radius, radius), Vec3(0.0f, 0.2f, 1.0f));
    scene.lights = defaultLights();
    return scene;
}

}  // namespace pt::cli
