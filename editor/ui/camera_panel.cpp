// Camera: field of view, depth of field (aperture radius or f-stop on a 35 mm full-frame
// sensor), focus distance with click-to-focus, reset, and bookmarks.
#include <cmath>
#include <string>

#include "assets/scene_loader.h"
#include "editor/scene_edits.h"
#include "editor/ui/widgets.h"

namespace pt::editor {
namespace {

constexpr float kSensorHeight = 0.024f;  // metres: full-frame 36 x 24 mm, as Blender's default

// Focal length (world units, taken as metres) that gives this vertical field of view.
float focalLength(const Camera& c) {
    return 0.5f * kSensorHeight / std::tan(0.5f * c.verticalFovDegrees * kPi / 180.0f);
}

void depthOfField(EditorUi& ui, Camera& c, bool& changed) {
    static bool useFStop = false;
    checkbox("Aperture as f-stop", &useFStop);
    if (useFStop) {
        // f-number N = focal length / aperture diameter.
        float n = c.apertureRadius > 0.0f ? focalLength(c) / (2.0f * c.apertureRadius) : 0.0f;
        if (sliderFloat(ui, "f-stop (0 = pinhole)", &n, 0.0f, 64.0f, "f/%.1f",
                        ImGuiSliderFlags_Logarithmic)) {
            c.apertureRadius = n > 0.0f ? focalLength(c) / (2.0f * n) : 0.0f;
            changed = true;
        }
    } else {
        changed |= sliderFloat(ui, "Aperture radius", &c.apertureRadius, 0.0f, 1.0f, "%.4f",
                               ImGuiSliderFlags_Logarithmic);
    }
    changed |= dragFloat(ui, "Focus distance", &c.focusDistance, 0.01f, 0.0f, 1e6f, "%.3f");
    ImGui::TextDisabled("Focus 0 = the look-at point. Double-click the viewport to focus there.");
}

void bookmarks(EditorUi& ui) {
    if (!ImGui::TreeNode("Bookmarks")) return;
    static char name[64] = "view";
    ImGui::InputText("##bookmark", name, sizeof(name));
    ImGui::SameLine();
    if (ImGui::Button("Add")) ui.bookmarks.push_back({name, ui.doc().scene.camera});
    for (size_t i = 0; i < ui.bookmarks.size(); ++i) {
        ImGui::PushID(int(i));
        if (ImGui::Button("Go")) {
            ui.apply(setCamera(ui.doc(), ui.bookmarks[i].camera));
            ui.endDrag();
        }
        ImGui::SameLine();
        if (ImGui::Button("X")) {
            ui.bookmarks.erase(ui.bookmarks.begin() + std::ptrdiff_t(i));
            ImGui::PopID();
            break;
        }
        ImGui::SameLine();
        ImGui::TextUnformatted(ui.bookmarks[i].name.c_str());
        ImGui::PopID();
    }
    ImGui::TreePop();
}

}  // namespace

void drawCameraPanel(EditorUi& ui) {
    if (!ImGui::CollapsingHeader("Camera")) return;
    Camera c = ui.doc().scene.camera;
    bool changed = false;
    changed |= sliderFloat(ui, "Vertical FOV", &c.verticalFovDegrees, 1.0f, 170.0f, "%.1f deg");
    changed |= dragVec3(ui, "Position", &c.position, 0.01f);
    changed |= dragVec3(ui, "Look at", &c.lookAt, 0.01f);
    depthOfField(ui, c, changed);
    if (changed) ui.apply(setCamera(ui.doc(), c));
    if (ImGui::Button("Reset to the file's camera")) {
        ui.apply(setCamera(ui.doc(), ui.fileCamera));
        ui.endDrag();
    }
    ImGui::SameLine();
    if (ImGui::Button("Frame the scene")) {
        ui.apply(setCamera(ui.doc(), frameBounds(ui.doc().scene)));
        ui.endDrag();
    }
    bookmarks(ui);
}

}  // namespace pt::editor
