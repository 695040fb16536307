#pragma once
// The viewport's color management: the OpenColorIO config the scene asks for (or the
// --ocio flag, $OCIO, the shipped config: assets/color_config.h) and the display / view / look
// of it the scene names, resolved once per change so that every frame draws with a known,
// valid view. When a config cannot be loaded or a view does not exist, the reason is kept for
// the Display panel and the viewport falls back to the built-in operators rather than going
// dark.
#include <memory>
#include <string>

#include "assets/color/color_config.h"
#include "assets/color/color_processor.h"
#include "editor/document.h"
#include "render/scene/scene.h"

namespace pt::editor {

struct ColorView {
    std::shared_ptr<const ColorConfig> config;  // null: none usable (see error), built-in operators only
    ViewTransform view;                         // complete (ColorConfig::resolve) when config is set
    std::string error;                          // why the scene's choice is not what is shown, or ""

    // Identifies the transform: equal keys draw alike (the editor rebuilds its shader on change).
    std::string key() const;
};

// The view for `settings` with the config found from `flagPath` (the --ocio flag) and
// settings.config. The config of `current` is reused when the path is the same, so choosing
// another view does not re-read the file. Never throws.
ColorView resolveColorView(const std::string& flagPath, const ColorSettings& settings,
                           const ColorView& current);

// The CPU form of what the viewport shows for `viewer` (exposure, then `color`'s OpenColorIO
// view, or the built-in operator where there is no config or the viewer asks for it), so an
// exported PNG holds the bytes the window displays. Throws InputError where OpenColorIO cannot
// build the processor.
DisplayProcessor displayProcessorFor(const ColorView& color, const ViewerSettings& viewer);

}  // namespace pt::editor
