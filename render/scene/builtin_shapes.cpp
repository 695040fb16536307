#include "render/scene/builtin_shapes.h"

#include "render/util/check.h"

namespace pt {

namespace {

const char* shapeMeshName(ObjectKind kind) {
    switch (kind) {
        case ObjectKind::Sphere: return "builtin:sphere";
        case ObjectKind::Box: return "builtin:box";
        case ObjectKind::Quad: return "builtin:quad";
        case ObjectKind::File: break;
    }
    return "";
}

// Appends a face spanning corner, corner + edgeU, corner + edgeU + edgeV, corner + edgeV,
// wound counter-clockwise when seen from the side `normal` points to.
void addFace(Mesh& mesh, Vec3 corner, Vec3 edgeU, Vec3 edgeV) {
    const Vec3 normal = normalize(cross(edgeU, edgeV));
    const uint32_t base = uint32_t(mesh.positions.size());
    const Vec3 corners[4] = {corner, corner + edgeU, corner + edgeU + edgeV, corner + edgeV};
    const Vec2 uvs[4] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
    for (int i = 0; i < 4; ++i) {
        mesh.positions.push_back(corners[i]);
        mesh.normals.push_back(normal);
        mesh.uvs.push_back(uvs[i]);
    }
    for (uint32_t i : {0u, 1u, 2u, 0u, 2u, 3u}) mesh.indices.push_back(base + i);
}

}  // namespace

Mesh makeUnitSphere() {
    Mesh mesh;
    mesh.name = shapeMeshName(ObjectKind::Sphere);
    mesh.kind = GeometryKind::Spheres;
    mesh.spheres.push_back({0.0f, 0.0f, 0.0f, 1.0f});
    return mesh;
}

Mesh makeUnitBox() {
    Mesh mesh;
    mesh.name = shapeMeshName(ObjectKind::Box);
    const Vec3 x{2, 0, 0}, y{0, 2, 0}, z{0, 0, 2};
    addFace(mesh, {-1, -1, 1}, x, y);   // +Z
    addFace(mesh, {1, -1, -1}, -x, y);  // -Z
    addFace(mesh, {1, -1, 1}, -z, y);   // +X
    addFace(mesh, {-1, -1, -1}, z, y);  // -X
    addFace(mesh, {-1, 1, 1}, x, -z);   // +Y
    addFace(mesh, {-1, -1, -1}, x, z);  // -Y
    return mesh;
}

Mesh makeUnitQuad() {
    Mesh mesh;
    mesh.name = shapeMeshName(ObjectKind::Quad);
    addFace(mesh, {-1, 0, 1}, {2, 0, 0}, {0, 0, -2});
    return mesh;
}

uint32_t builtinShapeMesh(Scene& scene, ObjectKind kind) {
    PT_CHECK(kind != ObjectKind::File);  // callers pass built-in shapes only
    const std::string name = shapeMeshName(kind);
    for (size_t i = 0; i < scene.meshes.size(); ++i) {
        if (scene.meshes[i].name == name) return uint32_t(i);
    }
    scene.meshes.push_back(kind == ObjectKind::Sphere ? makeUnitSphere()
                           : kind == ObjectKind::Box  ? makeUnitBox()
                                                      : makeUnitQuad());
    return uint32_t(scene.meshes.size() - 1);
}

}  // namespace pt
