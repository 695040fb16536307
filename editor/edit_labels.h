#pragma once
// What an edit of the camera, the render settings, the renderer toggles, the display or the
// environment changed, as the Edit menu and the history list name it ("Undo Display: exposure",
// not "Undo Display").
#include <string>

#include "editor/document.h"

namespace pt::editor {

std::string cameraEditLabel(const Camera& before, const Camera& after);
std::string renderSettingsEditLabel(const RenderSettings& before, const RenderSettings& after);
std::string togglesEditLabel(const IntegratorToggles& before, const IntegratorToggles& after);
std::string viewerEditLabel(const ViewerSettings& before, const ViewerSettings& after);
std::string environmentEditLabel(const Environment& before, const Environment& after);

}  // namespace pt::editor
