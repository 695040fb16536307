#pragma once
// Small ImGui helpers shared by the panels: every value widget edits a copy, and the panel
// turns a change into one command; a drag folds into one undo step that closes when the
// widget is released (STYLE.md rule 6).
#include <imgui.h>

#include <cstdio>
#include <cstring>
#include <string>

#include "editor/ui/editor_ui.h"

namespace pt::editor {

// Call right after a widget with its label at its right: where the column is too narrow for the
// label (the user drags it narrow; long labels at the default width), the label is cut at the
// window's edge, so hovering the widget shows the whole label.
inline void tooltipIfCut(const char* label) {
    if (!ImGui::IsItemHovered()) return;
    const float right = ImGui::GetWindowPos().x + ImGui::GetWindowContentRegionMax().x;
    if (ImGui::GetItemRectMax().x <= right + 0.5f) return;
    const char* hidden = std::strstr(label, "##");
    const std::string shown = hidden ? std::string(label, hidden) : std::string(label);
    if (!shown.empty()) ImGui::SetTooltip("%s", shown.c_str());
}

// ImGui::Checkbox with tooltipIfCut.
inline bool checkbox(const char* label, bool* v) {
    const bool changed = ImGui::Checkbox(label, v);
    tooltipIfCut(label);
    return changed;
}

// Call right after a widget: ends the undo step when its drag or text edit finished.
inline void closeStepIfReleased(EditorUi& ui) {
    if (ImGui::IsItemDeactivatedAfterEdit()) ui.endDrag();
}

// Widgets that report a change and close their step on release.
inline bool sliderFloat(EditorUi& ui, const char* label, float* v, float lo, float hi,
                        const char* format = "%.3f", ImGuiSliderFlags flags = 0) {
    const bool changed = ImGui::SliderFloat(label, v, lo, hi, format, flags);
    tooltipIfCut(label);
    closeStepIfReleased(ui);
    return changed;
}

// An angle held in radians, shown and edited in degrees over [loDegrees, hiDegrees].
inline bool sliderAngle(EditorUi& ui, const char* label, float* radians, float loDegrees, float hiDegrees) {
    const bool changed = ImGui::SliderAngle(label, radians, loDegrees, hiDegrees, "%.1f deg");
    tooltipIfCut(label);
    closeStepIfReleased(ui);
    return changed;
}

inline bool dragFloat(EditorUi& ui, const char* label, float* v, float speed, float lo = 0.0f,
                      float hi = 0.0f, const char* format = "%.3f") {
    const bool changed = ImGui::DragFloat(label, v, speed, lo, hi, format);
    tooltipIfCut(label);
    closeStepIfReleased(ui);
    return changed;
}

inline bool dragVec3(EditorUi& ui, const char* label, Vec3* v, float speed, const char* format = "%.3f") {
    float a[3] = {v->x, v->y, v->z};
    const bool changed = ImGui::DragFloat3(label, a, speed, 0.0f, 0.0f, format);
    tooltipIfCut(label);
    closeStepIfReleased(ui);
    if (changed) *v = Vec3(a[0], a[1], a[2]);
    return changed;
}

inline bool colorEdit(EditorUi& ui, const char* label, Vec3* v,
                      ImGuiColorEditFlags flags = ImGuiColorEditFlags_Float) {
    float a[3] = {v->x, v->y, v->z};
    const bool changed = ImGui::ColorEdit3(label, a, flags);
    tooltipIfCut(label);
    closeStepIfReleased(ui);
    if (changed) *v = Vec3(a[0], a[1], a[2]);
    return changed;
}

// Editable name: returns true with `name` changed once the user presses Enter or leaves the field.
inline bool inputName(const char* label, std::string& name) {
    char buffer[256];
    std::snprintf(buffer, sizeof(buffer), "%s", name.c_str());
    ImGui::InputText(label, buffer, sizeof(buffer));
    if (!ImGui::IsItemDeactivatedAfterEdit()) return false;
    name = buffer;
    return true;
}

}  // namespace pt::editor
