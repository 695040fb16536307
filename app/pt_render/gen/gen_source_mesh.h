#pragma once
// The mesh a field instances when given --mesh: every triangle mesh a model file places,
// merged into one (placements baked in), keeping positions, normals and indices only.
#include <string>

#include "render/scene/scene.h"
#include "render/util/progress.h"

namespace pt::cli {

// Throws std::runtime_error naming the file for unreadable or malformed input, a file with
// no triangles, or more than `maxTriangles`. Prints the importer's warnings on stderr.
Mesh loadMergedMesh(const std::string& path, uint64_t maxTriangles, const ProgressFn& progress = {});

}  // namespace pt::cli
