#include "assets/gltf/gltf_animation.h"

#include <cmath>
#include <stdexcept>

#include "assets/gltf/gltf_accessors.h"
#include "assets/gltf/gltf_values.h"

namespace pt {
namespace {

std::vector<int32_t> nodeParents(const GltfContext& ctx) {
    const auto& nodes = ctx.model().nodes;
    std::vector<int32_t> parents(nodes.size(), -1);
    for (size_t n = 0; n < nodes.size(); ++n) {
        for (int child : nodes[n].children) {
            gltfElement(ctx, nodes, child, gltfPath("nodes", n) + ".children", "node");
            if (parents[size_t(child)] >= 0) {
                ctx.fail(gltfPath("nodes", size_t(child)), "has two parents");
            }
            parents[size_t(child)] = int32_t(n);
        }
    }
    return parents;
}

std::vector<float> toFloats(const std::vector<double>& values) {
    return std::vector<float>(values.begin(), values.end());
}

// A column-major glTF 4x4 as an Affine3; InputError where the last row is not 0 0 0 1.
Affine3 affineFromColumns(const GltfContext& ctx, const float* m, const std::string& element) {
    constexpr float kTolerance = 1e-5f;
    if (std::fabs(m[3]) > kTolerance || std::fabs(m[7]) > kTolerance || std::fabs(m[11]) > kTolerance ||
        std::fabs(m[15] - 1.0f) > kTolerance) {
        ctx.fail(element, "not an affine transform (its last row must be 0 0 0 1)");
    }
    Affine3 a;
    for (int r = 0; r < 3; ++r) a.rows[r] = {m[r], m[4 + r], m[8 + r], m[12 + r]};
    return a;
}

size_t morphTargetsOf(const GltfContext& ctx, const tinygltf::Node& node) {
    if (node.mesh < 0 || size_t(node.mesh) >= ctx.model().meshes.size()) return 0;
    size_t count = 0;
    for (const auto& p : ctx.model().meshes[size_t(node.mesh)].primitives)
        count = std::max(count, p.targets.size());
    return count;
}

NodePose restPose(const GltfContext& ctx, size_t n) {
    const auto& node = ctx.model().nodes[n];
    const std::string element = gltfPath("nodes", n);
    NodePose pose;
    if (!node.matrix.empty()) {
        checkGltfNumbers(ctx, node.matrix, 16, element + ".matrix");
        const std::vector<float> m = toFloats(node.matrix);
        pose.fixed = true;
        pose.fixedMatrix = affineFromColumns(ctx, m.data(), element + ".matrix");
    }
    if (!node.translation.empty()) {
        checkGltfNumbers(ctx, node.translation, 3, element + ".translation");
        pose.translation = {float(node.translation[0]), float(node.translation[1]),
                            float(node.translation[2])};
    }
    if (!node.rotation.empty()) {
        checkGltfNumbers(ctx, node.rotation, 4, element + ".rotation");
        const auto& q = node.rotation;
        const double length = std::sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
        if (!(length > 1e-6)) ctx.fail(element + ".rotation", "not a unit quaternion");
        pose.rotation = {float(q[0] / length), float(q[1] / length), float(q[2] / length),
                         float(q[3] / length)};
    }
    if (!node.scale.empty()) {
        checkGltfNumbers(ctx, node.scale, 3, element + ".scale");
        pose.scale = {float(node.scale[0]), float(node.scale[1]), float(node.scale[2])};
    }
    const size_t targets = morphTargetsOf(ctx, node);
    if (targets > 0) {
        const std::vector<double>& given =
            !node.weights.empty() ? node.weights : ctx.model().meshes[size_t(node.mesh)].weights;
        pose.weights = given.size() == targets ? toFloats(given) : std::vector<float>(targets, 0.0f);
    }
    return pose;
}

Interpolation interpolationOf(const GltfContext& ctx, const std::string& name, const std::string& element) {
    if (name.empty() || name == "LINEAR") return Interpolation::Linear;
    if (name == "STEP") return Interpolation::Step;
    if (name == "CUBICSPLINE") return Interpolation::CubicSpline;
    ctx.fail(element + ".interpolation", "\"" + name + "\" is not STEP, LINEAR or CUBICSPLINE");
}

std::optional<AnimatedPath> pathOf(const std::string& path) {
    if (path == "translation") return AnimatedPath::Translation;
    if (path == "rotation") return AnimatedPath::Rotation;
    if (path == "scale") return AnimatedPath::Scale;
    if (path == "weights") return AnimatedPath::Weights;
    return std::nullopt;
}

KeyframeSampler readSampler(const GltfContext& ctx, const tinygltf::AnimationSampler& source,
                            uint32_t components, const std::string& element) {
    KeyframeSampler s;
    s.interpolation = interpolationOf(ctx, source.interpolation, element);
    s.times = readGltfFloats(ctx, source.input, 1, {element, std::string("input")});
    const std::string output = element + ".output";  // named: g++ 13 warns of a reference into a temporary
    const auto& accessor = gltfElement(ctx, ctx.model().accessors, source.output, output, "accessor");
    const int typeComponents = gltfTypeComponents(accessor.type);
    s.values = readGltfFloats(ctx, source.output, typeComponents, {element, std::string("output")});
    // Weights samplers are SCALAR: a key's value is every target's weight in a row.
    s.components = components;
    try {
        checkKeyframeSampler(s);
    } catch (const std::invalid_argument& e) {
        ctx.fail(element, e.what());
    }
    return s;
}

Animation readAnimation(const GltfContext& ctx, size_t a, const std::vector<NodePose>& rest) {
    const auto& source = ctx.model().animations[a];
    const std::string element = gltfPath("animations", a);
    Animation animation;
    animation.name = source.name.empty() ? "animation " + std::to_string(a) : source.name;
    // The components of each sampler follow from the path of the channels that use it.
    std::vector<uint32_t> components(source.samplers.size(), 0);
    for (size_t c = 0; c < source.channels.size(); ++c) {
        const auto& channel = source.channels[c];
        const std::string at = element + ".channels[" + std::to_string(c) + "]";
        gltfElement(ctx, source.samplers, channel.sampler, at + ".sampler", "sampler");
        const std::optional<AnimatedPath> path = pathOf(channel.target_path);
        if (!path) {
            ctx.warn(at, "path \"" + channel.target_path + "\" is not animated; ignored");
            continue;
        }
        if (channel.target_node < 0) {
            ctx.warn(at, "has no target node; ignored");
            continue;
        }
        const std::string target = at + ".target.node";
        const auto& node = gltfElement(ctx, ctx.model().nodes, channel.target_node, target, "node");
        if (!node.matrix.empty()) {
            ctx.warn(at, "animates a node given as a matrix, which glTF does not allow; ignored");
            continue;
        }
        const uint32_t wanted = *path == AnimatedPath::Rotation ? 4u
                                : *path == AnimatedPath::Weights
                                    ? uint32_t(rest[size_t(channel.target_node)].weights.size())
                                    : 3u;
        if (wanted == 0) {
            ctx.warn(at, "animates the weights of a node without morph targets; ignored");
            continue;
        }
        uint32_t& sampler = components[size_t(channel.sampler)];
        if (sampler != 0 && sampler != wanted) {
            ctx.fail(at, "shares its sampler with a channel of another kind");
        }
        sampler = wanted;
        animation.channels.push_back({uint32_t(channel.sampler), uint32_t(channel.target_node), *path});
    }
    for (size_t s = 0; s < source.samplers.size(); ++s) {
        const std::string at = element + ".samplers[" + std::to_string(s) + "]";
        // A sampler no honoured channel uses is kept (indices stay the file's) but never read.
        animation.samplers.push_back(
            components[s] == 0 ? KeyframeSampler{} : readSampler(ctx, source.samplers[s], components[s], at));
    }
    return animation;
}

Skin readSkin(const GltfContext& ctx, size_t k) {
    const auto& source = ctx.model().skins[k];
    const std::string element = gltfPath("skins", k);
    Skin skin;
    for (size_t j = 0; j < source.joints.size(); ++j) {
        gltfElement(ctx, ctx.model().nodes, source.joints[j], element + ".joints", "node");
        skin.joints.push_back(uint32_t(source.joints[j]));
    }
    if (skin.joints.empty()) ctx.fail(element, "has no joints");
    skin.inverseBindMatrices.assign(skin.joints.size(), Affine3{});
    if (source.inverseBindMatrices >= 0) {
        const std::vector<float> m = readGltfFloats(ctx, source.inverseBindMatrices, 16,
                                                    {element, std::string("inverseBindMatrices")});
        if (m.size() < 16 * skin.joints.size()) {
            ctx.fail(element + ".inverseBindMatrices", "has " + std::to_string(m.size() / 16) +
                                                           " matrices for " +
                                                           std::to_string(skin.joints.size()) + " joints");
        }
        for (size_t j = 0; j < skin.joints.size(); ++j) {
            for (size_t i = 0; i < 16; ++i) {
                if (!std::isfinite(m[16 * j + i])) ctx.fail(element + ".inverseBindMatrices", "not finite");
            }
            skin.inverseBindMatrices[j] =
                affineFromColumns(ctx, &m[16 * j], element + ".inverseBindMatrices");
        }
    }
    return skin;
}

}  // namespace

std::optional<AnimationRig> readGltfRig(const GltfContext& ctx) {
    const auto& model = ctx.model();
    if (model.skins.empty() && model.animations.empty()) return std::nullopt;
    AnimationRig rig;
    rig.parents = nodeParents(ctx);
    for (size_t n = 0; n < model.nodes.size(); ++n) rig.restPoses.push_back(restPose(ctx, n));
    try {
        globalTransforms(rig.parents, rig.restPoses);  // a cycle fails here, not at the first pose
    } catch (const std::invalid_argument& e) {
        ctx.fail("nodes", e.what());
    }
    for (size_t a = 0; a < model.animations.size(); ++a)
        rig.animations.push_back(readAnimation(ctx, a, rig.restPoses));
    for (size_t k = 0; k < model.skins.size(); ++k) rig.skins.push_back(readSkin(ctx, k));
    return rig;
}

void addGltfMorphedNodes(const GltfContext& ctx, AnimationRig& rig) {
    for (const Animation& animation : rig.animations) {
        for (const AnimationChannel& c : animation.channels) {
            if (c.path != AnimatedPath::Weights) continue;
            const auto found = ctx.meshes.find(ctx.model().nodes[c.node].mesh);
            if (found == ctx.meshes.end() || !found->second) continue;
            bool known = false;
            for (const MorphedNode& m : rig.morphedNodes) known |= m.node == c.node;
            if (!known) rig.morphedNodes.push_back({c.node, found->second->sceneMesh});
        }
    }
}

std::optional<SkinnedMesh> gltfSkinnedMesh(const GltfContext& ctx, const AnimationRig& rig, int node,
                                           const ImportedMesh& imported, uint32_t sceneMesh) {
    const std::string element = gltfPath("nodes", size_t(node));
    const int skin = ctx.model().nodes[size_t(node)].skin;
    gltfElement(ctx, rig.skins, skin, element + ".skin", "skin");
    if (imported.influences.empty()) {
        ctx.warn(element, "has a skin but its mesh has no JOINTS_0/WEIGHTS_0; shown unskinned");
        return std::nullopt;
    }
    const Mesh& mesh = ctx.scene.meshes[sceneMesh];
    SkinnedMesh skinned;
    skinned.mesh = sceneMesh;
    skinned.skin = uint32_t(skin);
    skinned.node = uint32_t(node);
    skinned.bindPositions = mesh.positions;
    skinned.bindNormals = mesh.normals;
    skinned.bindTangents = mesh.tangents;
    skinned.influences = imported.influences;
    try {
        const InfluenceCheck check =
            normalizeInfluences(skinned.influences, uint32_t(rig.skins[size_t(skin)].joints.size()));
        if (check.renormalized > 0) {
            ctx.warn(element, std::to_string(check.renormalized) +
                                  " vertices' skin weights did not sum to 1; normalised");
        }
    } catch (const std::invalid_argument& e) {
        ctx.fail(element + ".skin", e.what());
    }
    return skinned;
}

}  // namespace pt
