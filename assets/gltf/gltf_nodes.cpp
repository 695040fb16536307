#include "assets/gltf/gltf_nodes.h"

#include <cmath>

#include "assets/gltf/gltf_values.h"

namespace pt {
namespace {

// A column-major 4x4 glTF matrix; its last row must be (0 0 0 1): we render affine only.
Affine3 matrixTransform(const GltfContext& ctx, const std::vector<double>& m, const std::string& element) {
    checkGltfNumbers(ctx, m, 16, element);
    constexpr double kTolerance = 1e-6;
    if (std::abs(m[3]) > kTolerance || std::abs(m[7]) > kTolerance || std::abs(m[11]) > kTolerance ||
        std::abs(m[15] - 1.0) > kTolerance) {
        ctx.fail(element, "not an affine transform (its last row must be 0 0 0 1)");
    }
    Affine3 a;
    for (int r = 0; r < 3; ++r) {
        a.rows[r] = {float(m[size_t(r)]), float(m[size_t(4 + r)]), float(m[size_t(8 + r)]),
                     float(m[size_t(12 + r)])};
    }
    return a;
}

Affine3 localTransform(const GltfContext& ctx, const tinygltf::Node& node, const std::string& element) {
    if (!node.matrix.empty()) return matrixTransform(ctx, node.matrix, element + ".matrix");
    Affine3 t, r, s;
    if (!node.translation.empty()) {
        checkGltfNumbers(ctx, node.translation, 3, element + ".translation");
        const auto& v = node.translation;
        t = translationTransform({float(v[0]), float(v[1]), float(v[2])});
    }
    if (!node.rotation.empty()) {
        checkGltfNumbers(ctx, node.rotation, 4, element + ".rotation");
        const auto& q = node.rotation;
        r = gltfRotation(ctx, q[0], q[1], q[2], q[3], element + ".rotation");
    }
    if (!node.scale.empty()) {
        checkGltfNumbers(ctx, node.scale, 3, element + ".scale");
        const auto& v = node.scale;
        s = scaleTransform({float(v[0]), float(v[1]), float(v[2])});
    }
    return t * r * s;
}

std::vector<int> rootNodes(const GltfContext& ctx) {
    const auto& model = ctx.model();
    if (!model.scenes.empty()) {
        const int scene = model.defaultScene >= 0 ? model.defaultScene : 0;
        return gltfElement(ctx, model.scenes, scene, "scene", "scene").nodes;
    }
    std::vector<bool> isChild(model.nodes.size(), false);
    for (size_t n = 0; n < model.nodes.size(); ++n) {
        for (int child : model.nodes[n].children) {
            gltfElement(ctx, model.nodes, child, gltfPath("nodes", n) + ".children", "node");
            isChild[size_t(child)] = true;
        }
    }
    std::vector<int> roots;
    for (size_t n = 0; n < model.nodes.size(); ++n) {
        if (!isChild[n]) roots.push_back(int(n));
    }
    return roots;
}

}  // namespace

Affine3 gltfRotation(const GltfContext& ctx, double x, double y, double z, double w,
                     const std::string& element) {
    const double len = std::sqrt(x * x + y * y + z * z + w * w);
    if (!(len > 1e-6)) ctx.fail(element, "not a unit quaternion");
    // Exporters write quaternions rounded to a few digits; renormalize, do not reject.
    return rotationTransform({float(x / len), float(y / len), float(z / len), float(w / len)});
}

std::vector<GltfNodeVisit> walkGltfScene(const GltfContext& ctx) {
    const auto& model = ctx.model();
    std::vector<bool> reached(model.nodes.size(), false);
    std::vector<GltfNodeVisit> visits;
    std::vector<GltfNodeVisit> stack;  // holds the parent's world transform until visited
    const std::vector<int> roots = rootNodes(ctx);
    for (auto it = roots.rbegin(); it != roots.rend(); ++it) stack.push_back({*it, Affine3()});
    while (!stack.empty()) {
        GltfNodeVisit visit = stack.back();
        stack.pop_back();
        const std::string element = gltfPath("nodes", size_t(visit.node));
        const std::string sceneNodes = "scene nodes";
        const auto& node = gltfElement(ctx, model.nodes, visit.node, sceneNodes, "node");
        if (reached[size_t(visit.node)]) {
            ctx.fail(element,
                     "reached twice in the node hierarchy (a cycle, or a node with "
                     "two parents)");
        }
        reached[size_t(visit.node)] = true;
        visit.world = visit.world * localTransform(ctx, node, element);
        visits.push_back(visit);
        for (auto child = node.children.rbegin(); child != node.children.rend(); ++child) {
            gltfElement(ctx, model.nodes, *child, element + ".children", "node");
            stack.push_back({*child, visit.world});
        }
    }
    return visits;
}

std::optional<Camera> gltfCamera(const GltfContext& ctx, const std::vector<GltfNodeVisit>& visits) {
    const auto& model = ctx.model();
    for (const GltfNodeVisit& visit : visits) {
        const int index = model.nodes[size_t(visit.node)].camera;
        if (index < 0) continue;
        const std::string element = gltfPath("cameras", size_t(index));
        const std::string cameraElement = gltfPath("nodes", size_t(visit.node)) + ".camera";
        const auto& camera = gltfElement(ctx, model.cameras, index, cameraElement, "camera");
        if (camera.type != "perspective") {
            ctx.warn(element, "'" + camera.type + "' cameras are not supported; ignored");
            continue;
        }
        const double yfov = camera.perspective.yfov;
        if (!(yfov > 0.0 && yfov < kPi)) {
            ctx.fail(element + ".perspective.yfov", "must be in (0, pi) radians");
        }
        const Vec3 forward = visit.world.transformVector({0.0f, 0.0f, -1.0f});
        const Vec3 up = visit.world.transformVector({0.0f, 1.0f, 0.0f});
        if (!(length(forward) > 0.0f) || !(length(up) > 0.0f) || !isFinite(visit.world.translation())) {
            ctx.fail(gltfPath("nodes", size_t(visit.node)), "camera transform is degenerate");
        }
        Camera result;
        result.position = visit.world.translation();
        result.lookAt = result.position + normalize(forward);
        result.up = normalize(up);
        result.verticalFovDegrees = float(yfov * 180.0 / kPi);
        return result;
    }
    return std::nullopt;
}

}  // namespace pt
