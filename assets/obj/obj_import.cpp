// importObj: Wavefront OBJ + MTL through tinyobjloader, after obj_text_check has vetted the
// text. The whole file becomes one Scene Mesh with one slot per MTL material (plus one for
// faces without usemtl) and one placement with the identity transform.
//
// OBJ corners index positions, texcoords and normals separately; a Scene vertex is one
// distinct (v, vt, vn) triple. Faces without vn get generated normals: smooth (area-weighted,
// shared across UV seams) inside a smoothing group ("s 1"), flat where smoothing is off
// ("s off", the default), as Blender's importer does. Texcoords are flipped to glTF's
// convention (v' = 1 - v).
#include <algorithm>
#include <filesystem>
#include <limits>
#include <sstream>
#include <unordered_map>

#include "assets/input_error.h"
#include "assets/mesh_normals.h"
#include "assets/model_import.h"
#include "assets/obj/obj_materials.h"
#include "assets/obj/obj_text_check.h"
#include "assets/scene_append_guard.h"

namespace pt {
namespace {

// What makes two corners one vertex. Corners without a normal share a vertex only within a
// smoothing group (`group`); flat ones (`face` != 0) never share.
struct CornerKey {
    int v, vt, vn;
    unsigned group, face;
    bool operator==(const CornerKey& o) const {
        return v == o.v && vt == o.vt && vn == o.vn && group == o.group && face == o.face;
    }
};

struct CornerKeyHash {
    size_t operator()(const CornerKey& k) const {
        size_t h = size_t(k.v) * 0x9E3779B97F4A7C15ull;
        for (size_t part : {size_t(k.vt), size_t(k.vn), size_t(k.group), size_t(k.face)}) {
            h ^= part + 0x9E3779B97F4A7C15ull + (h << 6) + (h >> 2);
        }
        return h;
    }
};

struct MeshBuilder {
    const std::string& label;
    const tinyobj::attrib_t& attrib;
    Mesh mesh;
    std::vector<bool> regenerate;       // per vertex: normal to generate
    std::vector<uint32_t> normalGroup;  // per vertex: vertices sharing a generated normal
    std::unordered_map<CornerKey, uint32_t, CornerKeyHash> vertices;
    std::unordered_map<CornerKey, uint32_t, CornerKeyHash> groups;  // (v, group, face) -> id
    bool anyUv = false;

    // checkObjText vetted every index; this re-checks what tinyobjloader resolved.
    void checkIndices(const tinyobj::index_t& idx) const {
        if (idx.vertex_index < 0 || size_t(idx.vertex_index) >= attrib.vertices.size() / 3 ||
            size_t(idx.texcoord_index + 1) > attrib.texcoords.size() / 2 ||
            size_t(idx.normal_index + 1) > attrib.normals.size() / 3 || idx.texcoord_index < -1 ||
            idx.normal_index < -1) {
            throw InputError(label + ": a face corner indexes past the v, vt or vn entries");
        }
    }

    uint32_t vertex(const tinyobj::index_t& idx, unsigned smoothing, unsigned face) {
        checkIndices(idx);
        const bool flat = idx.normal_index < 0 && smoothing == 0;
        const CornerKey key{idx.vertex_index, idx.texcoord_index, idx.normal_index,
                            idx.normal_index < 0 ? smoothing : 0u, flat ? face + 1 : 0u};
        if (mesh.positions.size() == std::numeric_limits<uint32_t>::max()) {
            throw InputError(label + ": more than 2^32 - 1 distinct vertices");
        }
        auto [it, added] = vertices.emplace(key, uint32_t(mesh.positions.size()));
        if (!added) return it->second;
        const float* p = &attrib.vertices[3 * size_t(idx.vertex_index)];
        mesh.positions.push_back({p[0], p[1], p[2]});
        Vec2 uv;
        if (idx.texcoord_index >= 0) {
            const float* t = &attrib.texcoords[2 * size_t(idx.texcoord_index)];
            uv = {t[0], 1.0f - t[1]};
            anyUv = true;
        }
        mesh.uvs.push_back(uv);
        Vec3 n(0.0f);
        if (idx.normal_index >= 0) {
            const float* f = &attrib.normals[3 * size_t(idx.normal_index)];
            n = {f[0], f[1], f[2]};
        }
        const float len = length(n);
        regenerate.push_back(!(len > 0.0f));
        mesh.normals.push_back(len > 0.0f ? n / len : n);
        const CornerKey groupKey{idx.vertex_index, 0, 0, key.group, key.face};
        normalGroup.push_back(groups.emplace(groupKey, uint32_t(groups.size())).first->second);
        return it->second;
    }
};

// tinyobjloader's messages, one per line, each prefixed with the file name.
void addWarnings(const std::string& label, const std::string& text, Scene& scene) {
    std::istringstream lines(text);
    std::string line;
    while (std::getline(lines, line)) {
        if (!line.empty() && line != ".") scene.warnings.push_back(label + ": " + line);
    }
}

// Every face of every shape, its slot = its MTL material (or `defaultSlot`).
void addFaces(const std::string& label, const std::vector<tinyobj::shape_t>& shapes, size_t materialCount,
              uint32_t defaultSlot, MeshBuilder& b, std::vector<uint32_t>& slots) {
    unsigned faceNumber = 0;
    for (const tinyobj::shape_t& shape : shapes) {
        const tinyobj::mesh_t& m = shape.mesh;
        size_t corner = 0;
        for (size_t f = 0; f < m.num_face_vertices.size(); ++f, ++faceNumber) {
            const size_t n = m.num_face_vertices[f];
            if (n != 3 || corner + 3 > m.indices.size()) {
                throw InputError(label + ": shape '" + shape.name + "': face " + std::to_string(f) +
                                 " was not triangulated");
            }
            const int material = f < m.material_ids.size() ? m.material_ids[f] : -1;
            const unsigned smoothing = f < m.smoothing_group_ids.size() ? m.smoothing_group_ids[f] : 0;
            for (size_t k = 0; k < 3; ++k) {
                b.mesh.indices.push_back(b.vertex(m.indices[corner + k], smoothing, faceNumber));
            }
            slots.push_back(material >= 0 && size_t(material) < materialCount ? uint32_t(material)
                                                                              : defaultSlot);
            corner += n;
        }
    }
}

tinyobj::ObjReader readObj(const std::string& path, const std::string& label, const std::string& dir,
                           const ObjTextFacts& facts, Scene& scene) {
    tinyobj::ObjReaderConfig config;
    config.triangulate = true;
    config.vertex_color = false;
    config.mtl_search_path = dir.empty() ? "." : dir;
    tinyobj::ObjReader reader;
    if (!reader.ParseFromFile(path, config) || !reader.Error().empty()) {
        throw InputError(label + ": " + reader.Error());
    }
    addWarnings(label, reader.Warning(), scene);
    if (facts.linesAndPoints > 0) {
        scene.warnings.push_back(label + ": " + std::to_string(facts.linesAndPoints) +
                                 " line and point elements are not rendered; skipped");
    }
    return reader;
}

// The mesh of every face, normals complete; slots[t] is triangle t's slot.
Mesh buildMesh(const std::string& label, const tinyobj::ObjReader& reader, uint32_t defaultSlot,
               std::vector<uint32_t>& slots) {
    MeshBuilder builder{label, reader.GetAttrib(), {}, {}, {}, {}, {}, false};
    addFaces(label, reader.GetShapes(), reader.GetMaterials().size(), defaultSlot, builder, slots);
    if (builder.mesh.indices.empty()) throw InputError(label + ": no faces to render");
    generateAreaWeightedNormals(builder.mesh.positions, builder.mesh.indices, builder.regenerate,
                                builder.mesh.normals, &builder.normalGroup);
    if (!builder.anyUv) builder.mesh.uvs.clear();
    return std::move(builder.mesh);
}

}  // namespace

ImportedFile importObj(const std::string& path, int32_t object, Scene& scene, const ProgressFn& progress) {
    const std::string label = std::filesystem::path(path).filename().string();
    const std::string dir = std::filesystem::path(path).parent_path().string();
    reportProgress(progress, "load OBJ", 0.0);
    SceneAppendGuard guard(scene);
    const ObjTextFacts facts = checkObjText(path, label);
    reportProgress(progress, "load OBJ", 0.2);
    const tinyobj::ObjReader reader = readObj(path, label, dir, facts, scene);
    reportProgress(progress, "load OBJ", 0.6);

    const auto& materials = reader.GetMaterials();
    const uint32_t defaultSlot = uint32_t(materials.size());
    std::vector<uint32_t> slots;
    Mesh mesh = buildMesh(label, reader, defaultSlot, slots);
    mesh.name = std::filesystem::path(path).stem().string();

    ObjMaterialContext materialCtx{label, dir, object, scene, facts, {}};
    Placement placement;
    placement.name = mesh.name;
    for (const tinyobj::material_t& mtl : materials) {
        placement.materials.push_back(importObjMaterial(materialCtx, mtl));
    }
    if (std::find(slots.begin(), slots.end(), defaultSlot) != slots.end() || materials.empty()) {
        placement.materials.push_back(importObjDefaultMaterial(materialCtx));
    }
    mesh.slotCount = uint32_t(placement.materials.size());
    if (mesh.slotCount > 1) mesh.primitiveSlots = std::move(slots);
    placement.mesh = uint32_t(scene.meshes.size());
    scene.meshes.push_back(std::move(mesh));

    ImportedFile file;
    file.placements.push_back(std::move(placement));
    reportProgress(progress, "load OBJ", 1.0);
    guard.commit();
    return file;
}

}  // namespace pt
