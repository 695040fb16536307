#include "editor/ui/file_picker.h"

#include <GLFW/glfw3.h>
#include <imgui.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <optional>

#include "editor/ui/input_events.h"

namespace pt::editor {
namespace {

namespace fs = std::filesystem;

// The last item double-clicked: ImGui's own test, or a double-click press event inside it (at a
// few frames a second ImGui misses most double-clicks: input_events.h).
bool itemDoubleClicked() {
    if (ImGui::IsItemHovered() && ImGui::IsMouseDoubleClicked(ImGuiMouseButton_Left)) return true;
    const std::optional<ScreenPoint> at = inputEvents().doubleClick(GLFW_MOUSE_BUTTON_LEFT);
    const ImVec2 lo = ImGui::GetItemRectMin(), hi = ImGui::GetItemRectMax();
    return at && at->x >= lo.x && at->x < hi.x && at->y >= lo.y && at->y < hi.y;
}

}  // namespace

bool dialogCancelled() {
    const bool button = ImGui::Button("Cancel");
    return button || (!ImGui::IsWindowAppearing() && inputEvents().tapped(GLFW_KEY_ESCAPE));
}

void PathField::set(const std::string& s) { std::snprintf(text, sizeof(text), "%s", s.c_str()); }

bool pathFieldEntered(const char* label, PathField& path) {
    const bool entered =
        ImGui::InputText(label, path.text, sizeof(path.text), ImGuiInputTextFlags_EnterReturnsTrue);
    return entered || (ImGui::IsItemActive() && inputEvents().tapped(GLFW_KEY_ENTER));
}

void FilePicker::start(const std::string& path, const std::string& sceneFolder) {
    sceneFolder_ = sceneFolder;
    field_.set(path);
    browser_.open(startFolder(path));
}

void FilePicker::go(const std::string& folder) {
    if (!browser_.open(folder)) return;
    folderChanged_ = true;
    if (keepsName_ && field_.text[0] == '\0') return;  // an empty field (no file wanted) stays so
    const std::string name = keepsName_ ? fs::path(field_.text).filename().string() : std::string();
    field_.set((fs::path(browser_.folder()) / name).string());
}

void FilePicker::placesRow() {
    if (ImGui::SmallButton("Up")) go(fs::path(browser_.folder()).parent_path().string());
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("The folder above");
    // The folder's last few parents as buttons (a deep path would run off the dialog).
    constexpr size_t kCrumbs = 6;
    const auto crumbs = browser_.crumbs();
    for (size_t i = crumbs.size() > kCrumbs ? crumbs.size() - kCrumbs : 0; i < crumbs.size(); ++i) {
        const auto& [label, folder] = crumbs[i];
        ImGui::SameLine(0.0f, 2.0f);
        ImGui::PushID(folder.c_str());
        if (ImGui::SmallButton(label.c_str())) go(folder);
        ImGui::PopID();
    }
    if (const char* home = std::getenv("HOME")) {
        if (ImGui::SmallButton("Home")) go(home);
        ImGui::SameLine();
    }
    std::error_code ec;
    const fs::path here = fs::current_path(ec);
    if (!ec && ImGui::SmallButton("Working folder")) go(here.string());
    if (!sceneFolder_.empty()) {
        ImGui::SameLine();
        if (ImGui::SmallButton("Scene's folder")) go(sceneFolder_);
    }
    ImGui::SameLine();
    bool hidden = browser_.showsHidden();
    if (ImGui::Checkbox("Hidden files", &hidden)) browser_.setShowHidden(hidden);
}

bool FilePicker::list(float height) {
    bool chosen = false;
    ImGui::BeginChild("##listing", ImVec2(0.0f, height), true);
    const std::string fileName = fs::path(field_.text).filename().string();
    std::string enter;
    for (const FileEntry& e : browser_.entries()) {
        if (e.folder) {
            if (ImGui::Selectable((e.name + "/").c_str(), false)) enter = e.name;
            continue;
        }
        if (ImGui::Selectable(e.name.c_str(), e.name == fileName, ImGuiSelectableFlags_AllowDoubleClick)) {
            field_.set(browser_.pathOf(e.name));
            fileClicked_ = true;
        }
        if (itemDoubleClicked()) {
            field_.set(browser_.pathOf(e.name));
            chosen = true;
        }
        ImGui::SameLine(ImGui::GetWindowContentRegionMax().x - 80.0f);
        ImGui::TextDisabled("%s", sizeText(e.bytes).c_str());
    }
    if (browser_.entries().empty()) ImGui::TextDisabled("(no folders or files of these kinds here)");
    ImGui::EndChild();
    if (!enter.empty()) go(browser_.pathOf(enter));  // after the loop: it replaces the listing
    return chosen;
}

bool FilePicker::draw(const char* fieldLabel, float width, float listHeight) {
    folderChanged_ = fileClicked_ = false;
    ImGui::PushID(fieldLabel);
    placesRow();
    if (!browser_.error().empty())
        ImGui::TextColored(ImVec4(1, 0.5f, 0.4f, 1), "%s", browser_.error().c_str());
    bool chosen = list(listHeight);
    ImGui::SetNextItemWidth(width);
    if (ImGui::IsWindowAppearing()) ImGui::SetKeyboardFocusHere();  // type, then Return
    if (pathFieldEntered(fieldLabel, field_)) {
        std::error_code ec;
        if (fs::is_directory(field_.text, ec))
            go(field_.text);  // a folder typed: list it
        else
            chosen = true;
    }
    ImGui::PopID();
    return chosen;
}

}  // namespace pt::editor
