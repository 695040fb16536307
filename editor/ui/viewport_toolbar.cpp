// The viewport's toolbar, over its top left corner: the transform gizmo's mode, axes and
// snapping, and whether the Stats figures are shown over the viewport.
#include "editor/ui/viewport_toolbar.h"

#include <imgui.h>

namespace pt::editor {

void drawViewportToolbar(EditorUi& ui, GizmoTool& gizmo, const ImageRect& image) {
    ImGui::SetNextWindowPos(ImVec2(image.x + 6.0f, image.y + 6.0f));
    ImGui::SetNextWindowBgAlpha(0.65f);
    ImGui::Begin("##viewport toolbar", nullptr,
                 ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_AlwaysAutoResize |
                     ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoMove |
                     ImGuiWindowFlags_NoFocusOnAppearing);
    gizmo.toolbarItems();
    ImGui::SameLine();
    ImGui::Checkbox("Stats", &ui.layout.statsOverlay);
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("The main Stats figures over the viewport (remembered)");
    ImGui::End();
    drawStatsOverlay(ui, image);
}

}  // namespace pt::editor
