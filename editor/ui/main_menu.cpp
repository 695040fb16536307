// The menu bar: File (open, recent, save, export, quit), Edit (undo/redo with the command's
// name, and the history list), Window (panels floating in windows of their own, the Stats
// overlay).
#include <GLFW/glfw3.h>

#include <string>
#include <vector>

#include "editor/ui/widgets.h"

namespace pt::editor {
namespace {

// Edit > History: every step since the file was opened, the current one checked; choosing one
// undoes or redoes to it.
void drawHistory(EditorUi& ui) {
    const CommandStack& history = ui.session.history();
    if (!ImGui::BeginMenu("History", history.canUndo() || history.canRedo())) return;
    const std::vector<std::string> done = history.undoLabels(), undone = history.redoLabels();
    int steps = 0;  // > 0: undo that many; < 0: redo
    if (ImGui::MenuItem("Opened", nullptr, done.empty())) steps = int(done.size());
    for (size_t i = 0; i < done.size(); ++i) {
        ImGui::PushID(int(i));
        if (ImGui::MenuItem(done[i].c_str(), nullptr, i + 1 == done.size())) steps = int(done.size() - 1 - i);
        ImGui::PopID();
    }
    for (size_t i = 0; i < undone.size(); ++i) {
        ImGui::PushID(int(done.size() + i));
        ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyleColorVec4(ImGuiCol_TextDisabled));
        if (ImGui::MenuItem(undone[i].c_str())) steps = -int(i + 1);
        ImGui::PopStyleColor();
        ImGui::PopID();
    }
    ImGui::EndMenu();
    for (; steps > 0; --steps) ui.undo();
    for (; steps < 0; ++steps) ui.redo();
}

}  // namespace

void drawMainMenu(EditorUi& ui) {
    if (!ImGui::BeginMainMenuBar()) return;
    if (ImGui::BeginMenu("File")) {
        if (ImGui::MenuItem("Open...", "Ctrl+O")) ui.showOpenDialog = true;
        if (ImGui::BeginMenu("Open Recent", !ui.recentFiles.empty())) {
            for (const std::string& path : ui.recentFiles) {
                if (ImGui::MenuItem(path.c_str())) ui.openScene(path);
            }
            ImGui::EndMenu();
        }
        ImGui::Separator();
        if (ImGui::MenuItem("Save Scene", "Ctrl+S")) ui.showSaveDialog = true;
        if (ImGui::MenuItem("Export Render...", "Ctrl+E")) ui.showExportDialog = true;
        ImGui::Separator();
        if (ImGui::MenuItem("Quit", "Ctrl+Q")) ui.quit(glfwGetCurrentContext());
        ImGui::EndMenu();
    }
    if (ImGui::BeginMenu("Edit")) {
        const CommandStack& history = ui.session.history();
        const std::string undo = "Undo " + history.undoLabel(), redo = "Redo " + history.redoLabel();
        if (ImGui::MenuItem(undo.c_str(), "Ctrl+Z", false, history.canUndo())) ui.undo();
        if (ImGui::MenuItem(redo.c_str(), "Ctrl+Shift+Z", false, history.canRedo())) ui.redo();
        drawHistory(ui);
        ImGui::EndMenu();
    }
    if (ImGui::BeginMenu("Window")) {
        // A checked panel floats in a window of its own; closing that window docks it back.
        for (const char* panel : kPanelNames) {
            if (ImGui::MenuItem(panel, nullptr, ui.layout.floats(panel)))
                ui.layout.setFloating(panel, !ui.layout.floats(panel));
        }
        if (ImGui::MenuItem("Dock all panels", nullptr, false, !ui.layout.floating.empty()))
            ui.layout.floating.clear();
        ImGui::Separator();
        ImGui::MenuItem("Stats overlay", nullptr, &ui.layout.statsOverlay);
        ImGui::EndMenu();
    }
    ImGui::EndMainMenuBar();
}

}  // namespace pt::editor
