#pragma once
// Importers append to a Scene that may already hold other objects (the editor adds a model
// to an open scene). If an import throws halfway, this puts the Scene's meshes, materials,
// textures and warnings back to what they were, so bad input leaves no half-imported
// object behind. Internal to pt_assets.
#include "render/scene/scene.h"

namespace pt {

class SceneAppendGuard {
public:
    explicit SceneAppendGuard(Scene& scene)
        : scene_(scene),
          meshes_(scene.meshes.size()),
          materials_(scene.materials.size()),
          textures_(scene.textures.size()),
          warnings_(scene.warnings.size()) {}
    SceneAppendGuard(const SceneAppendGuard&) = delete;
    SceneAppendGuard& operator=(const SceneAppendGuard&) = delete;
    ~SceneAppendGuard() {
        if (committed_) return;
        scene_.meshes.resize(meshes_);
        scene_.materials.resize(materials_);
        scene_.textures.resize(textures_);
        scene_.warnings.resize(warnings_);
    }

    void commit() { committed_ = true; }

private:
    Scene& scene_;
    size_t meshes_, materials_, textures_, warnings_;
    bool committed_ = false;
};

}  // namespace pt
