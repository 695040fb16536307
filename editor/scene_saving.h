#pragma once
// Saving an edited scene as scene JSON. Materials imported from model files are not written
// into scene JSON (they come back from their files on load), so an edit to one would be lost;
// here each edited imported material is written as a scene material and its object gets a
// materialOverride naming it, which the loader applies on top of the file.
#include <string>
#include <vector>

#include "render/scene/scene.h"

namespace pt::editor {

// Writes `scene` to `path` atomically. `importedAtLoad` holds every material's parameters as
// loaded (index for index); imported materials that differ from it are saved as overrides.
// The scene itself is left as it was. Throws InputError naming the file on failure.
void saveSceneJson(Scene& scene, const std::vector<Material>& importedAtLoad, const std::string& path);

// Parameters of every material, for saveSceneJson's `importedAtLoad`.
std::vector<Material> materialParams(const Scene& scene);

}  // namespace pt::editor
