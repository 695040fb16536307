#pragma once
// The file dialogs' body (Open, Save, Export, the environment image): the in-app browser of one
// folder (editor/file_browser.h) above a path field. Up, the folder's parents as buttons, Home,
// the working folder and the scene's folder move the listing; a click on a folder goes in, a
// click on a file puts its path in the field, a double-click on a file chooses it, and Return in
// the field chooses what it holds (or, where that is a folder, lists it).
#include <string>
#include <vector>

#include "editor/file_browser.h"

namespace pt::editor {

// A text field holding a path between frames.
struct PathField {
    char text[1024] = {};
    void set(const std::string& s);
};

// A path field that Return confirms. ImGui 1.86 sees Return only if it is down when a frame
// starts, so a quick press and release within one slow frame was lost (the file was not saved
// or opened); the press event (InputEvents) counts too while the field has the keyboard.
bool pathFieldEntered(const char* label, PathField& path);

// A dialog's Cancel button, or Escape pressed while the dialog is up (not the press that opened
// it).
bool dialogCancelled();

class FilePicker {
public:
    // `keepsName`: moving to another folder moves the field's file name along (Save, Export);
    // else the field shows the folder (Open).
    FilePicker(std::vector<std::string> extensions, bool keepsName)
        : browser_(std::move(extensions)), keepsName_(keepsName) {}

    // Lists the folder of `path` (its start folder) and puts `path` in the field.
    void start(const std::string& path, const std::string& sceneFolder);
    // Draws the browser `listHeight` tall and the field `width` wide; true when the user chose
    // a file this frame.
    bool draw(const char* fieldLabel, float width, float listHeight);
    std::string path() const { return field_.text; }
    void setPath(const std::string& path) { field_.set(path); }
    const FileBrowser& browser() const { return browser_; }
    // The listing moved to another folder this frame.
    bool folderChanged() const { return folderChanged_; }
    // A file of the listing was clicked this frame (its path is in the field).
    bool fileClicked() const { return fileClicked_; }

private:
    void placesRow();
    void go(const std::string& folder);
    bool list(float height);

    FileBrowser browser_;
    PathField field_;
    std::string sceneFolder_;
    bool keepsName_;
    bool folderChanged_ = false, fileClicked_ = false;
};

}  // namespace pt::editor
