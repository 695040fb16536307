// Modal dialogs: errors (one at a time; the current scene always stays), open with a path field
// and recent files, save with overwrite confirmation, export render (paths, EXR pixel type and
// AOV layers), unsaved edits before they would be lost, and load progress.
#include <GLFW/glfw3.h>

#include <cstdio>
#include <filesystem>
#include <string>

#include "assets/image/exr_layers.h"
#include "editor/scene_edits.h"
#include "editor/ui/file_picker.h"
#include "editor/ui/input_events.h"
#include "editor/ui/widgets.h"

namespace pt::editor {
namespace {

namespace fs = std::filesystem;

constexpr float kFieldWidth = 620.0f, kListHeight = 260.0f;

// The folder the document's file is in ("" for a scene never saved).
std::string sceneFolder(const EditorUi& ui) {
    const std::string& source = ui.doc().scene.sourcePath;
    return source.empty() ? std::string() : fs::absolute(source).parent_path().string();
}

std::string defaultScenePath(const Scene& scene) {
    if (scene.sourcePath.empty()) return "scene.json";
    fs::path p(scene.sourcePath);
    return p.extension() == ".json" ? p.string() : p.replace_extension(".json").string();
}

// One error at a time (warnings go to the status bar). Return or Escape dismiss it only as a
// new press after it appeared: ImGui's IsKeyPressed also answers a held key's repeats, so the
// Return that opened a broken file, held a moment, dismissed its error before it was seen
// (issue 20, defect 4).
void errorDialog(EditorUi& ui) {
    if (ui.errors.empty()) return;
    const std::string& message = ui.errors.front();
    if (!ImGui::IsPopupOpen("Error")) ImGui::OpenPopup("Error");
    if (ImGui::BeginPopupModal("Error", nullptr, ImGuiWindowFlags_AlwaysAutoResize)) {
        ImGui::PushTextWrapPos(600.0f);
        ImGui::TextUnformatted(message.c_str());
        ImGui::PopTextWrapPos();
        const bool keys = !ImGui::IsWindowAppearing();
        if (ImGui::Button("OK") ||
            (keys && (inputEvents().tapped(GLFW_KEY_ENTER) || inputEvents().tapped(GLFW_KEY_ESCAPE)))) {
            ui.errors.erase(ui.errors.begin());
            ImGui::CloseCurrentPopup();
        }
        ImGui::EndPopup();
    }
}

void openDialog(EditorUi& ui) {
    static FilePicker picker({".json", ".gltf", ".glb", ".obj"}, false);
    if (ui.showOpenDialog) {
        // Where the last Open left off (what was typed stays), else the scene's folder.
        const std::string folder = sceneFolder(ui);
        const std::string last = picker.path();
        picker.start(!last.empty() ? last : folder.empty() ? std::string() : folder + "/", folder);
        ImGui::OpenPopup("Open scene");
        ui.showOpenDialog = false;
    }
    if (!ImGui::BeginPopupModal("Open scene", nullptr, ImGuiWindowFlags_AlwaysAutoResize)) return;
    ImGui::TextUnformatted(".json, .gltf, .glb or .obj (or drop a file on the window)");
    const bool chosen = picker.draw("Path", kFieldWidth, kListHeight);
    if (!ui.recentFiles.empty()) ImGui::TextDisabled("Recent:");
    for (const std::string& recent : ui.recentFiles) {
        if (ImGui::Selectable(recent.c_str())) picker.setPath(recent);
    }
    if (ImGui::Button("Open") || chosen) {
        ui.openScene(picker.path());
        ImGui::CloseCurrentPopup();
    }
    ImGui::SameLine();
    if (dialogCancelled()) ImGui::CloseCurrentPopup();
    ImGui::EndPopup();
}

void saveDialog(EditorUi& ui) {
    static FilePicker picker({".json"}, true);
    if (ui.showSaveDialog) {
        picker.start(fs::absolute(defaultScenePath(ui.doc().scene)).string(), sceneFolder(ui));
        ImGui::OpenPopup("Save scene");
        ui.showSaveDialog = false;
    }
    if (ImGui::BeginPopupModal("Save scene", nullptr, ImGuiWindowFlags_AlwaysAutoResize)) {
        const bool chosen = picker.draw("JSON path", kFieldWidth, kListHeight);
        if (ImGui::Button("Save") || chosen) {
            ui.saveScene(picker.path(), false);
            ImGui::CloseCurrentPopup();
        }
        ImGui::SameLine();
        if (dialogCancelled()) ImGui::CloseCurrentPopup();
        ImGui::EndPopup();
    }
    if (!ui.pendingOverwrite.empty()) ImGui::OpenPopup("Replace file?");
    if (ImGui::BeginPopupModal("Replace file?", nullptr, ImGuiWindowFlags_AlwaysAutoResize)) {
        ImGui::Text("%s exists and is not the scene's own file. Replace it?", ui.pendingOverwrite.c_str());
        if (ImGui::Button("Replace")) {
            const std::string target = ui.pendingOverwrite;
            ui.pendingOverwrite.clear();
            ui.saveScene(target, true);
            ImGui::CloseCurrentPopup();
        }
        ImGui::SameLine();
        if (dialogCancelled()) {
            ui.pendingOverwrite.clear();
            ImGui::CloseCurrentPopup();
        }
        ImGui::EndPopup();
    }
}

// Changes the viewer's export settings through a command, like every other document edit.
void setExportSettings(EditorUi& ui, AovMask aovs, bool half) {
    const ViewerSettings& viewer = ui.doc().viewer;
    if (aovs == viewer.exportAovs && half == viewer.exportHalf) return;
    ViewerSettings next = viewer;
    next.exportAovs = aovs;
    next.exportHalf = half;
    ui.apply(setViewer(ui.doc(), next));
}

// The EXR's pixel type and AOV layers. AOVs are accumulated only while chosen here (or shown),
// so a change restarts accumulation; chosen ones not accumulated yet are named, since an
// export now leaves them out.
void exrLayerChoice(EditorUi& ui) {
    const ViewerSettings& viewer = ui.doc().viewer;
    int half = viewer.exportHalf ? 1 : 0;
    ImGui::TextUnformatted("EXR pixels:");
    ImGui::SameLine();
    ImGui::RadioButton("float (32-bit)", &half, 0);
    ImGui::SameLine();
    ImGui::RadioButton("half (16-bit)", &half, 1);
    ImGui::TextDisabled("In half files too, ids, sample_count, depth and position stay 32-bit float.");

    AovMask chosen = viewer.exportAovs;
    ImGui::TextUnformatted("AOV layers:");
    ImGui::SameLine();
    if (ImGui::SmallButton("all")) chosen = kAllAovs;
    ImGui::SameLine();
    if (ImGui::SmallButton("none")) chosen = 0;
    for (uint32_t i = 0; i < kAovCount; ++i) {
        const AovMask bit = aovBit(Aov(i));
        bool on = (chosen & bit) != 0;
        if (i % 4 != 0) ImGui::SameLine(float(i % 4) * 150.0f + 8.0f);
        if (ImGui::Checkbox(aovName(Aov(i)), &on)) chosen ^= bit;
    }
    setExportSettings(ui, chosen, half == 1);
    ImGui::TextDisabled(
        "Changing the layers restarts accumulation: AOVs accumulate only while chosen or displayed.");
    const AovMask missing = chosen & ~ui.worker.status().aovs;
    if (missing) {
        ImGui::PushTextWrapPos(600.0f);
        ImGui::TextColored(ImVec4(1, 0.6f, 0.3f, 1), "Not accumulated yet, left out of an export now: %s",
                           aovListText(missing, ", ").c_str());
        ImGui::PopTextWrapPos();
    }
}

// The EXR's path is the picker's; the display image's follows it into the folder it browses to,
// and takes a clicked PNG, JPEG or TIFF.
void exportDialog(EditorUi& ui) {
    static FilePicker exr({".exr", ".png", ".jpg", ".jpeg", ".tif", ".tiff"}, true);
    static PathField display;
    if (ui.showExportDialog) {
        const fs::path base = fs::absolute(defaultScenePath(ui.doc().scene)).replace_extension("");
        exr.start(base.string() + ".exr", sceneFolder(ui));
        display.set(base.string() + ".png");
        ImGui::OpenPopup("Export render");
        ui.showExportDialog = false;
    }
    if (!ImGui::BeginPopupModal("Export render", nullptr, ImGuiWindowFlags_AlwaysAutoResize)) return;
    ImGui::TextUnformatted(
        "Scene-linear EXR with AOV layers, and a display-referred image (PNG, JPEG or TIFF by");
    ImGui::TextUnformatted(
        "extension, through the current display settings). Leave a path empty to skip that file.");
    ImGui::TextUnformatted("Existing files are replaced.");
    const std::string before = exr.path();
    exr.draw("EXR", kFieldWidth, 0.6f * kListHeight);
    if (exr.fileClicked() && fs::path(exr.path()).extension() != ".exr") {
        display.set(exr.path());  // a display image clicked: it is that field's, the EXR's stays
        exr.setPath(before);
    } else if (exr.folderChanged() && display.text[0] != '\0') {
        display.set((fs::path(exr.browser().folder()) / fs::path(display.text).filename()).string());
    }
    ImGui::SetNextItemWidth(kFieldWidth);
    ImGui::InputText("Display image", display.text, sizeof(display.text));
    ImGui::Separator();
    exrLayerChoice(ui);
    ImGui::Separator();
    ImGui::Text("%u samples per pixel so far", ui.lastFrame.stats.samplesPerPixel);
    if (ImGui::Button("Export")) {
        ui.exportRender(exr.path(), display.text);
        ImGui::CloseCurrentPopup();
    }
    ImGui::SameLine();
    if (dialogCancelled()) ImGui::CloseCurrentPopup();
    ImGui::EndPopup();
}

void loadingDialog(EditorUi& ui) {
    if (!ui.loading) return;
    ImGui::OpenPopup("Loading");
    if (ImGui::BeginPopupModal("Loading", nullptr, ImGuiWindowFlags_AlwaysAutoResize)) {
        ImGui::Text("%s", ui.loading->path().c_str());
        ImGui::ProgressBar(float(ui.loading->fraction()), ImVec2(400, 0), ui.loading->stage().c_str());
        if (ui.loading->done()) ImGui::CloseCurrentPopup();
        ImGui::EndPopup();
    }
}

}  // namespace

// Before an action that would lose unsaved edits (askBeforeDiscarding): save them into the
// scene's own JSON file (where it has one; Return) and go on, go on without them, or cancel
// (Escape). A save that fails shows its error and goes nowhere.
void unsavedEditsDialog(EditorUi& ui) {
    if (!ui.discardAction) return;
    if (!ImGui::IsPopupOpen("Unsaved edits")) ImGui::OpenPopup("Unsaved edits");
    if (!ImGui::BeginPopupModal("Unsaved edits", nullptr, ImGuiWindowFlags_AlwaysAutoResize)) return;
    const std::string source = ui.doc().scene.sourcePath;
    const bool savable = !source.empty() && fs::path(source).extension() == ".json";
    ImGui::Text("The scene has edits that are not saved. %s loses them.", ui.discardWhat.c_str());
    if (!savable)
        ImGui::TextUnformatted("(It came from a model file: Cancel, then File > Save Scene as JSON.)");
    // Keys from the frame that opened the dialog (the Return of the Open dialog) are not answers.
    const bool keys = !ImGui::IsWindowAppearing();
    const auto close = [&ui](bool go) {
        std::function<void()> action = std::move(ui.discardAction);
        ui.discardAction = nullptr;
        ui.discardWhat.clear();
        ImGui::CloseCurrentPopup();
        if (go) action();
    };
    bool save = false;
    if (savable) {
        save = ImGui::Button("Save") || (keys && inputEvents().tapped(GLFW_KEY_ENTER));
        ImGui::SameLine();
    }
    const bool discard = ImGui::Button("Don't save");
    ImGui::SameLine();
    const bool cancel = ImGui::Button("Cancel") || (keys && inputEvents().tapped(GLFW_KEY_ESCAPE));
    if (save) {
        ui.saveScene(source, true);
        close(!ui.session.modified());
    } else if (discard || cancel) {
        close(discard);
    }
    ImGui::EndPopup();
}

void drawDialogs(EditorUi& ui) {
    loadingDialog(ui);
    openDialog(ui);
    saveDialog(ui);
    exportDialog(ui);
    unsavedEditsDialog(ui);
    errorDialog(ui);
}

}  // namespace pt::editor
