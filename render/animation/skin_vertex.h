#pragma once
// Linear blend skinning of one vertex (Magnenat-Thalmann et al. 1988, "Joint-dependent local
// deformations for hand animation and object grasping"; the model glTF 2.0 specifies in
// section 3.7.3): the vertex moves by the weighted sum of its joints' matrices. Per-vertex and
// shared, so the CUDA backend can run it over a mesh's vertices as the CPU does.
#include <cstdint>

#include "render/math/affine.h"
#include "render/math/hd.h"

namespace pt {

// Up to eight joints a vertex (glTF JOINTS_0/WEIGHTS_0 and JOINTS_1/WEIGHTS_1); unused entries
// have weight 0.
constexpr uint32_t kMaxJointInfluences = 8;
struct JointInfluences {
    uint16_t joints[kMaxJointInfluences] = {};  // indices into the skin's joint list
    float weights[kMaxJointInfluences] = {};    // >= 0, summing to 1 (normalizeInfluences)
};

// The blended matrix sum_i w_i J_i; the identity for a vertex without weight (left where its
// mesh node puts it).
PT_HD Affine3 blendJointMatrices(const Affine3* jointMatrices, const JointInfluences& v) {
    Affine3 m;
    float total = 0.0f;
    for (int r = 0; r < 3; ++r) m.rows[r] = Vec4(0.0f, 0.0f, 0.0f, 0.0f);
    for (uint32_t i = 0; i < kMaxJointInfluences; ++i) {
        const float w = v.weights[i];
        if (w == 0.0f) continue;
        const Affine3& j = jointMatrices[v.joints[i]];
        for (int r = 0; r < 3; ++r) {
            m.rows[r].x += w * j.rows[r].x;
            m.rows[r].y += w * j.rows[r].y;
            m.rows[r].z += w * j.rows[r].z;
            m.rows[r].w += w * j.rows[r].w;
        }
        total += w;
    }
    return total > 0.0f ? m : Affine3{};
}

// A normal under `m`: the inverse transpose of its linear part, taken as the cofactor matrix
// times the sign of the determinant (the same direction, defined even where m is singular),
// normalised; the input where the result vanishes.
PT_HD Vec3 skinNormal(const Affine3& m, Vec3 n) {
    const float a = m.at(0, 0), b = m.at(0, 1), c = m.at(0, 2);
    const float d = m.at(1, 0), e = m.at(1, 1), f = m.at(1, 2);
    const float g = m.at(2, 0), h = m.at(2, 1), i = m.at(2, 2);
    const Vec3 skinned{(e * i - f * h) * n.x + (f * g - d * i) * n.y + (d * h - e * g) * n.z,
                       (c * h - b * i) * n.x + (a * i - c * g) * n.y + (b * g - a * h) * n.z,
                       (b * f - c * e) * n.x + (c * d - a * f) * n.y + (a * e - b * d) * n.z};
    const float sign = m.determinant() < 0.0f ? -1.0f : 1.0f;
    const float length2 = dot(skinned, skinned);
    return length2 > 0.0f ? skinned * (sign / sqrtf(length2)) : n;
}

// A tangent (xyz along increasing U, w the bitangent's handedness) under `m`: xyz through the
// linear part, normalised; w flips where m mirrors, so that w x cross(normal, tangent) stays
// the skinned bitangent. A zero tangent (no tangent at that vertex) stays zero.
PT_HD Vec4 skinTangent(const Affine3& m, Vec4 t) {
    const Vec3 skinned = m.transformVector(Vec3(t.x, t.y, t.z));
    const float length2 = dot(skinned, skinned);
    if (!(length2 > 0.0f)) return t;
    const Vec3 unit = skinned * (1.0f / sqrtf(length2));
    return {unit.x, unit.y, unit.z, m.determinant() < 0.0f ? -t.w : t.w};
}

}  // namespace pt
