// Outliner: the scene's objects (with the instances a file placed), lights and camera. Select,
// rename, hide, duplicate and delete; each is an undoable command.
#include <string>

#include "assets/scene_loader.h"
#include "editor/object_edits.h"
#include "editor/ui/widgets.h"

namespace pt::editor {
namespace {

bool isSelected(const Selection& s, Selection::Kind kind, int32_t index) {
    return s.kind == kind && s.index == index;
}

void objectContextMenu(EditorUi& ui, uint32_t object) {
    if (!ImGui::BeginPopupContextItem()) return;
    const Scene& scene = ui.doc().scene;
    std::string name = scene.objects[object].name;
    if (inputName("Name", name)) ui.apply(renameObject(ui.doc(), object, name));
    const bool hidden = objectHidden(scene, object);
    if (ImGui::MenuItem(hidden ? "Show" : "Hide", "H")) ui.apply(setObjectHidden(ui.doc(), object, !hidden));
    if (ImGui::MenuItem("Duplicate", "Ctrl+D")) ui.duplicateBeside(object);
    if (ImGui::MenuItem("Delete", "Del")) {
        ui.apply(deleteObject(ui.doc(), object));
        ui.selection = {};
    }
    ImGui::EndPopup();
}

void lightContextMenu(EditorUi& ui, uint32_t light) {
    if (!ImGui::BeginPopupContextItem()) return;
    std::string name = ui.doc().scene.lights[light].name;
    if (inputName("Name", name)) ui.apply(renameLight(ui.doc(), light, name));
    if (ImGui::MenuItem("Duplicate")) ui.apply(duplicateLight(ui.doc(), light));
    if (ImGui::MenuItem("Delete")) {
        ui.apply(deleteLight(ui.doc(), light));
        ui.selection = {};
    }
    ImGui::EndPopup();
}

void drawObjects(EditorUi& ui) {
    const Scene& scene = ui.doc().scene;
    for (uint32_t o = 0; o < scene.objects.size(); ++o) {
        ImGui::PushID(int(o));
        const std::string label =
            objectDisplayName(scene.objects[o]) + (objectHidden(scene, o) ? "  (hidden)" : "");
        std::vector<uint32_t> instances;
        for (uint32_t i = 0; i < scene.instances.size(); ++i) {
            if (scene.instances[i].object == int32_t(o)) instances.push_back(i);
        }
        ImGuiTreeNodeFlags flags = ImGuiTreeNodeFlags_OpenOnArrow | ImGuiTreeNodeFlags_SpanAvailWidth;
        if (instances.size() <= 1) flags |= ImGuiTreeNodeFlags_Leaf | ImGuiTreeNodeFlags_NoTreePushOnOpen;
        if (isSelected(ui.selection, Selection::Kind::Object, int32_t(o)))
            flags |= ImGuiTreeNodeFlags_Selected;
        const bool open = ImGui::TreeNodeEx(label.c_str(), flags);
        if (ImGui::IsItemClicked() && !ImGui::IsItemToggledOpen()) {
            ui.selection = {Selection::Kind::Object, int32_t(o),
                            instances.empty() ? -1 : int32_t(instances[0])};
        }
        objectContextMenu(ui, o);
        if (open && instances.size() > 1) {
            for (uint32_t i : instances) {
                const bool selected = ui.selection.instance == int32_t(i) && ui.selection.index == int32_t(o);
                if (ImGui::Selectable(scene.instances[i].name.c_str(), selected)) {
                    ui.selection = {Selection::Kind::Object, int32_t(o), int32_t(i)};
                }
            }
            ImGui::TreePop();
        }
        ImGui::PopID();
    }
    // Instances no object placed (scenes built in code).
    for (uint32_t i = 0; i < scene.instances.size(); ++i) {
        if (scene.instances[i].object >= 0) continue;
        ImGui::PushID(int(100000 + i));
        if (ImGui::Selectable(scene.instances[i].name.c_str(),
                              isSelected(ui.selection, Selection::Kind::Instance, int32_t(i)))) {
            ui.selection = {Selection::Kind::Instance, int32_t(i), int32_t(i)};
        }
        ImGui::PopID();
    }
}

}  // namespace

void drawOutliner(EditorUi& ui) {
    if (!ImGui::CollapsingHeader("Outliner", ImGuiTreeNodeFlags_DefaultOpen)) return;
    ImGui::BeginChild("outliner", ImVec2(0, 180), true);
    if (ImGui::Selectable("Camera", ui.selection.kind == Selection::Kind::Camera)) {
        ui.selection = {Selection::Kind::Camera, 0, -1};
    }
    drawObjects(ui);
    const Scene& scene = ui.doc().scene;
    for (uint32_t l = 0; l < scene.lights.size(); ++l) {
        ImGui::PushID(int(200000 + l));
        const std::string label =
            "Light: " + (scene.lights[l].name.empty() ? std::to_string(l) : scene.lights[l].name);
        if (ImGui::Selectable(label.c_str(), isSelected(ui.selection, Selection::Kind::Light, int32_t(l)))) {
            ui.selection = {Selection::Kind::Light, int32_t(l), -1};
        }
        lightContextMenu(ui, l);
        ImGui::PopID();
    }
    ImGui::EndChild();
    ImGui::PushTextWrapPos(0.0f);  // wrapped at the column's edge, not cut
    ImGui::TextDisabled("Right-click: rename, hide, duplicate, delete.");
    ImGui::PopTextWrapPos();
}

}  // namespace pt::editor
