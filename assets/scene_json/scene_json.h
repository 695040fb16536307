#pragma once
// Scene JSON (schema in scenes/README.md): read and write. Reading resolves paths relative
// to the JSON file and imports the model files it references; writing stores paths relative
// to the output file, leaves out every value equal to its default, and replaces the file
// atomically.
#include <string>

#include "render/scene/scene.h"
#include "render/util/progress.h"

namespace pt {

constexpr int kSceneJsonVersion = 1;

// The material a shape gets when its JSON names none; added to the scene's materials once,
// after the JSON-defined ones, unless the JSON defines a material of this name itself.
constexpr const char* kDefaultMaterialName = "default";

// The camera's vertical field of view must lie in (0, 180) degrees for the reader.
// withinFileRanges holds an edited one to [kMinEditedFov, kMaxEditedFov], well inside, and its
// aperture to a finite number >= 0, so that a saved scene reopens.
constexpr float kMinEditedFov = 0.01f, kMaxEditedFov = 179.0f;
Camera withinFileRanges(const Camera& camera);

// Throws InputError naming the file and the JSON path of the bad element, e.g.
// "scene.json: objects[3].transform.scale: expected 3 numbers".
Scene readSceneJson(const std::string& path, const ProgressFn& progress = {});

// The scene as JSON text, paths relative to `outputPath`'s folder.
std::string sceneToJson(const Scene& scene, const std::string& outputPath);

// Throws InputError on failure; the previous file at `path` survives any failure.
void writeSceneJson(const Scene& scene, const std::string& path);

}  // namespace pt
