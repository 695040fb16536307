#include "pt_render/gen/gen_source_mesh.h"

#include <cstdio>
#include <filesystem>
#include <stdexcept>

#include "assets/model_import.h"

namespace pt::cli {

namespace {

// Appends `mesh` placed by `toFile`; a mirroring placement has its winding flipped so that
// front faces stay front faces once the transform is baked in.
void appendPlaced(const Mesh& mesh, const Affine3& toFile, Mesh& merged) {
    const uint32_t base = uint32_t(merged.positions.size());
    const Affine3 normalTransform = inverse(toFile);
    for (size_t v = 0; v < mesh.positions.size(); ++v) {
        merged.positions.push_back(toFile.transformPoint(mesh.positions[v]));
        const Vec3 n = mesh.normals.empty() ? Vec3(0.0f, 0.0f, 1.0f)
                                            : normalTransform.transformNormalByInverse(mesh.normals[v]);
        merged.normals.push_back(length(n) > 0.0f ? normalize(n) : Vec3(0.0f, 0.0f, 1.0f));
    }
    const bool mirrored = toFile.determinant() < 0.0f;
    for (size_t i = 0; i < mesh.indices.size(); i += 3) {
        merged.indices.push_back(base + mesh.indices[i]);
        merged.indices.push_back(base + mesh.indices[i + (mirrored ? 2 : 1)]);
        merged.indices.push_back(base + mesh.indices[i + (mirrored ? 1 : 2)]);
    }
}

}  // namespace

Mesh loadMergedMesh(const std::string& path, uint64_t maxTriangles, const ProgressFn& progress) {
    namespace fs = std::filesystem;
    std::error_code error;
    if (!fs::is_regular_file(path, error)) throw std::runtime_error(path + ": no such file");
    Scene scratch;
    SceneObject object;
    object.path = fs::absolute(path).lexically_normal().string();
    scratch.objects.push_back(object);
    ImportedFile file;
    try {
        file = importModelFile(object.path, 0, scratch, progress);
    } catch (const std::exception& e) {
        const std::string message = e.what();
        // Importer messages name the file already; others (out of memory) get its name.
        const bool named = message.find(fs::path(path).filename().string()) != std::string::npos;
        throw std::runtime_error(named ? message : path + ": " + message);
    }
    for (const std::string& warning : scratch.warnings)
        std::fprintf(stderr, "warning: %s\n", warning.c_str());

    uint64_t triangles = 0, vertices = 0;
    for (const Placement& placement : file.placements) {
        const Mesh& mesh = scratch.meshes[placement.mesh];
        if (mesh.kind != GeometryKind::Triangles) continue;
        triangles += mesh.indices.size() / 3;
        vertices += mesh.positions.size();
    }
    if (triangles == 0) throw std::runtime_error(path + ": no triangles to instance");
    if (triangles > maxTriangles || vertices > 0xffffffffull) {
        throw std::runtime_error(path + ": " + std::to_string(triangles) +
                                 " triangles; a field mesh has at most " + std::to_string(maxTriangles));
    }
    Mesh merged;
    merged.name = fs::path(path).stem().string();
    merged.positions.reserve(size_t(vertices));
    merged.normals.reserve(size_t(vertices));
    merged.indices.reserve(size_t(triangles) * 3);
    for (const Placement& placement : file.placements) {
        const Mesh& mesh = scratch.meshes[placement.mesh];
        if (mesh.kind == GeometryKind::Triangles) appendPlaced(mesh, placement.fileToNode, merged);
    }
    return merged;
}

}  // namespace pt::cli
