#include "render/animation/skinning.h"

#include <tbb/parallel_for.h>

#include <cmath>
#include <stdexcept>
#include <string>

namespace pt {

std::vector<Affine3> globalTransforms(const std::vector<int32_t>& parents,
                                      const std::vector<NodePose>& poses) {
    const size_t n = poses.size();
    if (parents.size() != n) throw std::invalid_argument("node parents and poses differ in count");
    std::vector<Affine3> globals(n);
    std::vector<uint8_t> state(n, 0);  // 0 not done, 1 on the current chain, 2 done
    std::vector<size_t> chain;
    for (size_t start = 0; start < n; ++start) {
        // Walk up to a done node or a root, then fill the chain downwards.
        for (size_t i = start; state[i] != 2;) {
            if (state[i] == 1)
                throw std::invalid_argument("node " + std::to_string(i) + " is its own ancestor");
            state[i] = 1;
            chain.push_back(i);
            const int32_t p = parents[i];
            if (p < 0) break;
            if (size_t(p) >= n) {
                throw std::invalid_argument("node " + std::to_string(i) + " names parent " +
                                            std::to_string(p) + ", which does not exist");
            }
            i = size_t(p);
        }
        for (auto it = chain.rbegin(); it != chain.rend(); ++it) {
            const int32_t p = parents[*it];
            globals[*it] = p < 0 ? poses[*it].matrix() : globals[size_t(p)] * poses[*it].matrix();
            state[*it] = 2;
        }
        chain.clear();
    }
    return globals;
}

std::vector<Affine3> jointMatrices(const Skin& skin, const std::vector<Affine3>& nodeGlobals,
                                   const Affine3& meshNodeGlobal) {
    const Affine3 toMesh = inverse(meshNodeGlobal);
    std::vector<Affine3> matrices(skin.joints.size());
    for (size_t j = 0; j < skin.joints.size(); ++j) {
        if (skin.joints[j] >= nodeGlobals.size()) {
            throw std::invalid_argument("skin joint " + std::to_string(j) + " names node " +
                                        std::to_string(skin.joints[j]) + ", which does not exist");
        }
        const Affine3 inverseBind =
            j < skin.inverseBindMatrices.size() ? skin.inverseBindMatrices[j] : Affine3{};
        matrices[j] = toMesh * nodeGlobals[skin.joints[j]] * inverseBind;
    }
    return matrices;
}

InfluenceCheck normalizeInfluences(std::vector<JointInfluences>& influences, uint32_t jointCount) {
    InfluenceCheck check;
    for (size_t v = 0; v < influences.size(); ++v) {
        JointInfluences& in = influences[v];
        double total = 0.0;
        for (uint32_t i = 0; i < kMaxJointInfluences; ++i) {
            const float w = in.weights[i];
            if (!(w >= 0.0f) || !std::isfinite(w)) {
                throw std::invalid_argument("vertex " + std::to_string(v) + ": weight " + std::to_string(i) +
                                            " is negative or not finite");
            }
            if (w > 0.0f && in.joints[i] >= jointCount) {
                throw std::invalid_argument("vertex " + std::to_string(v) + ": joint " +
                                            std::to_string(in.joints[i]) + " is past the skin's " +
                                            std::to_string(jointCount) + " joints");
            }
            total += w;
        }
        if (total == 0.0) {
            ++check.unweighted;
        } else if (std::fabs(total - 1.0) > 1e-3) {
            for (float& w : in.weights) w = float(w / total);
            ++check.renormalized;
        }
    }
    return check;
}

void skinVertices(const std::vector<Affine3>& matrices, const BindPose& bind, std::vector<Vec3>& positions,
                  std::vector<Vec3>& normals, std::vector<Vec4>& tangents) {
    const size_t n = bind.positions.size();
    if (bind.influences.size() != n)
        throw std::invalid_argument("skinning: influences and positions differ in count");
    positions.resize(n);
    const bool withNormals = bind.normals.size() == n, withTangents = bind.tangents.size() == n;
    if (withNormals) normals.resize(n);
    if (withTangents) tangents.resize(n);
    tbb::parallel_for(tbb::blocked_range<size_t>(0, n, 4096), [&](const tbb::blocked_range<size_t>& range) {
        for (size_t v = range.begin(); v != range.end(); ++v) {
            const Affine3 m = blendJointMatrices(matrices.data(), bind.influences[v]);
            positions[v] = m.transformPoint(bind.positions[v]);
            if (withNormals) normals[v] = skinNormal(m, bind.normals[v]);
            if (withTangents) tangents[v] = skinTangent(m, bind.tangents[v]);
        }
    });
}

}  // namespace pt
