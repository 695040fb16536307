#pragma once
// loadScene: the one entry point that turns a file (.json, .gltf, .glb, .obj) into a Scene.
// Bad input never throws out of here: the result carries one message naming the file and
// the element.
#include <optional>
#include <string>

#include "render/scene/scene.h"
#include "render/util/progress.h"

namespace pt {

struct LoadResult {
    std::optional<Scene> scene;
    std::string error;  // set when !scene

    bool ok() const { return scene.has_value(); }
};

LoadResult loadScene(const std::string& path, const ProgressFn& progress = {});

// A model file on its own (no JSON): one object, the file's camera or a camera framing the
// bounds, default render settings. Throws InputError.
Scene sceneFromModelFile(const std::string& path, const ProgressFn& progress = {});

// Places an object's imported file into the scene: instances under its transform, material
// overrides by name applied. Throws InputError for an override naming an unknown material.
void instantiateImportedFile(const ImportedFile& file, int32_t objectIndex, Scene& scene);

// A camera looking at the scene's bounds from the front (+Z), for scenes that have none.
Camera frameBounds(const Scene& scene);

}  // namespace pt
