#pragma once
#include "editor/ui/display_view.h"
#include "editor/ui/editor_ui.h"
#include "editor/ui/gizmo_tool.h"

namespace pt::editor {

// The toolbar over the viewport's top left corner (the gizmo's mode, axes and snapping; the
// Stats overlay switch) and, where switched on, the Stats overlay at the bottom right.
void drawViewportToolbar(EditorUi& ui, GizmoTool& gizmo, const ImageRect& image);

}  // namespace pt::editor
