#pragma once
// Document: everything an editor command may change. The scene is what gets saved; the
// toggles and display settings are the session's renderer and viewer state, undoable like
// scene edits (STYLE.md rule 6) but never written into scene JSON.
#include "render/backend/backend.h"
#include "render/display/display_transform.h"
#include "render/scene/scene.h"

namespace pt::editor {

struct ViewerSettings {
    DisplaySettings display;  // exposure, dither; the built-in operator when builtinDisplay
    // The built-in operators instead of the scene's OpenColorIO view (Scene::color), e.g. to
    // compare the two, or where no config loads.
    bool builtinDisplay = false;
    int32_t aov = -1;  // -1: the beauty; else a pt::Aov value
    // Passes per render step (more: fewer syncs, slower UI); 0: automatic (step_passes.h).
    uint32_t samplesPerFrame = 0;
    uint32_t targetSpp = 0;  // stop accumulating here; 0 = never stop
    // Export: AOV layers for the EXR. They are accumulated beside the displayed AOV from the
    // next pass on (Backend::changeAovs); exportRender writes those that are.
    AovMask exportAovs = 0;
    bool exportHalf = false;  // 16-bit EXR channels (exr_layers.h: which stay float)
    // The beauty shown (and exported beside the raw one) through the denoiser. Its guides are
    // accumulated from the reset that turning it on makes; turning it off keeps them, so that
    // switching back and forth is a display change.
    bool denoise = false;
    // The render's size follows the viewport's (the window's pixels times `resolutionScale`,
    // a quarter a side while the camera moves: viewport_resolution.h) instead of the scene's
    // resolution, which saving keeps as the file had it. Off where --size fixes the size.
    bool followViewport = true;
    float resolutionScale = 1.0f;
};

struct Document {
    Scene scene;
    IntegratorToggles toggles;
    ViewerSettings viewer;
    // Where animation edits skin (render/scene/scene_animation.h): on the device where the
    // session's backend skins there (EditorSession keeps it so), else on the host.
    SkinningSite skinning = SkinningSite::Host;
};

}  // namespace pt::editor
