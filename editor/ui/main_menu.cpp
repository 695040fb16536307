// The menu bar: File (open, recent, save, export, quit), Edit (undo/redo with the command's
// name), Display (AOV), View (camera bookmarks).
#include <GLFW/glfw3.h>

#include "editor/ui/widgets.h"

namespace pt::editor {

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
        ImGui::EndMenu();
    }
    ImGui::EndMainMenuBar();
}

}  // namespace pt::editor
