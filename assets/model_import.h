#pragma once
// Importers for model files (.gltf, .glb, .obj). An importer appends the file's meshes,
// materials and textures to a Scene and returns *placements*: which mesh goes where, in the
// file's own space. The caller turns placements into instances under an object transform, so
// a file referenced twice is imported once and its meshes are shared.
#include <optional>
#include <string>
#include <vector>

#include "render/scene/scene.h"
#include "render/util/progress.h"

namespace pt {

struct Placement {
    std::string name;                 // node name (glTF) or object/group name (OBJ)
    uint32_t mesh = 0;                // Scene::meshes index
    Affine3 fileToNode;               // node-to-file-root transform (glTF node hierarchy)
    std::vector<uint32_t> materials;  // Scene::materials index per mesh slot
    // Per variant of the file (ImportedFile::variants), the Scene material of each slot; empty
    // when no variant maps a material of this mesh.
    std::vector<std::vector<uint32_t>> variantMaterials;
    // glTF: the node that placed it (-1: none, OBJ) and, for an EXT_mesh_gpu_instancing
    // instance, its own transform under the node's; the rig poses instances through these.
    int32_t node = -1;
    Affine3 extra;
};

struct ImportedFile {
    std::vector<Placement> placements;
    std::optional<Camera> camera;       // the file's first camera, in file space
    std::vector<Light> lights;          // punctual lights (glTF KHR_lights_punctual), in file space
    std::vector<std::string> variants;  // material variants (glTF KHR_materials_variants), by name
    // glTF skins and animations (render/animation/rig.h), without instances: the caller adds
    // the instances it makes of the placements. nullopt where the file has neither.
    std::optional<AnimationRig> rig;
};

// Throws InputError naming the file and the element for malformed or unsupported-fatal input;
// appends non-fatal warnings (each naming file, mesh, primitive) to scene.warnings.
// `object` is stored in the materials and textures it adds (their `object` field).
ImportedFile importGltf(const std::string& path, int32_t object, Scene& scene,
                        const ProgressFn& progress = {});
ImportedFile importObj(const std::string& path, int32_t object, Scene& scene,
                       const ProgressFn& progress = {});

// Picks the importer by extension (case-insensitive); throws InputError for others.
ImportedFile importModelFile(const std::string& path, int32_t object, Scene& scene,
                             const ProgressFn& progress = {});

}  // namespace pt
