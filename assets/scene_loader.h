#pragma once
// loadScene: the one entry point that turns a file (.json, .gltf, .glb, .obj) into a Scene.
// Bad input never throws out of here: the result carries one message naming the file and
// the element.
#include <optional>
#include <string>

#include "assets/model_import.h"
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
// overrides by name applied, and the file's punctual lights placed under the same transform.
// Throws InputError for an override naming an unknown material.
void instantiateImportedFile(const ImportedFile& file, int32_t objectIndex, Scene& scene);

// Whether any instanced material emits light.
bool sceneHasEmitters(const Scene& scene);

// Gives a scene with no light at all (no emitters, no punctual lights, black environment) a uniform white
// environment, with a warning; used for model files opened on their own.
void lightUnlitModel(Scene& scene);

// A camera looking at the scene's bounds from the front (+Z), for scenes that have none.
Camera frameBounds(const Scene& scene);

// True for the extensions importModelFile reads (.gltf, .glb, .obj; any case).
bool isModelFile(const std::string& path);

// A file's camera (in file space) placed in the world under its object's transform; focus
// distance and aperture scale with the transform along the view direction.
Camera cameraToWorld(const Camera& camera, const Affine3& objectToWorld);

// A material defined by the scene itself (NamedMaterial::object == -1), by name: the
// materials scene JSON objects may name. -1 when there is none.
int32_t findSceneMaterial(const Scene& scene, const std::string& name);

// "sphere", "box", "quad" (the scene JSON names); "" for File.
const char* shapeKindName(ObjectKind kind);

// The object's name, else its file's stem or its shape's name; instances are named after it.
std::string objectDisplayName(const SceneObject& object);

}  // namespace pt
