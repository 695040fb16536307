#include "assets/gltf/gltf_instancing.h"

#include "assets/gltf/gltf_accessors.h"
#include "assets/gltf/gltf_nodes.h"

namespace pt {
namespace {

constexpr const char* kExtension = "EXT_mesh_gpu_instancing";

// Accessor `name` of the extension's attributes, -1 when absent.
int attributeAccessor(const GltfContext& ctx, const tinygltf::Value& attributes, const char* name,
                      const std::string& element) {
    if (!attributes.Has(name)) return -1;
    const tinygltf::Value& v = attributes.Get(name);
    if (!v.IsInt() || v.Get<int>() < 0) ctx.fail(element + "." + name, "is not an accessor index");
    return v.Get<int>();
}

}  // namespace

std::vector<Affine3> gltfInstanceTransforms(const GltfContext& ctx, int node) {
    const auto& extensions = ctx.model().nodes[size_t(node)].extensions;
    const auto it = extensions.find(kExtension);
    if (it == extensions.end()) return {};
    const std::string element = gltfPath("nodes", size_t(node)) + ".extensions." + kExtension + ".attributes";
    if (!it->second.Has("attributes") || !it->second.Get("attributes").IsObject())
        ctx.fail(element, "missing: an instanced node needs its attributes");
    const tinygltf::Value& attributes = it->second.Get("attributes");
    const int accessors[3] = {attributeAccessor(ctx, attributes, "TRANSLATION", element),
                              attributeAccessor(ctx, attributes, "ROTATION", element),
                              attributeAccessor(ctx, attributes, "SCALE", element)};
    const char* const roles[3] = {"TRANSLATION", "ROTATION", "SCALE"};
    const int components[3] = {3, 4, 3};
    std::vector<float> values[3];
    size_t count = 0;
    bool any = false;
    for (int a = 0; a < 3; ++a) {
        if (accessors[a] < 0) continue;
        const std::string role = roles[a];
        values[a] = readGltfFloats(ctx, accessors[a], components[a], {element, role});
        const size_t n = values[a].size() / size_t(components[a]);
        if (any && n != count)
            ctx.fail(element + "." + role, "has " + std::to_string(n) + " instances, the other attributes " +
                                               std::to_string(count));
        count = n;
        any = true;
    }
    if (!any) ctx.fail(element, "has none of TRANSLATION, ROTATION and SCALE");
    std::vector<Affine3> transforms(count);
    for (size_t i = 0; i < count; ++i) {
        Affine3 t, r, s;
        if (const float* v = values[0].empty() ? nullptr : &values[0][3 * i])
            t = translationTransform({v[0], v[1], v[2]});
        if (const float* q = values[1].empty() ? nullptr : &values[1][4 * i])
            r = gltfRotation(ctx, q[0], q[1], q[2], q[3], element + ".ROTATION[" + std::to_string(i) + "]");
        if (const float* v = values[2].empty() ? nullptr : &values[2][3 * i])
            s = scaleTransform({v[0], v[1], v[2]});
        transforms[i] = t * r * s;
    }
    return transforms;
}

}  // namespace pt
