#pragma once
// The in-app file browser's model, without a window: one folder's entries (folders first, then
// the files with the extensions asked for, each sorted by name without regard to case; names
// starting with a dot left out unless asked), moving into a folder and up, and the folder a
// dialog starts in. An unreadable folder keeps the listing shown and says why in one line.
// The dialogs (editor/ui/file_browser_view.h) draw it.
#include <cstdint>
#include <string>
#include <vector>

namespace pt::editor {

struct FileEntry {
    std::string name;
    bool folder = false;
    uintmax_t bytes = 0;  // files only
};

class FileBrowser {
public:
    // `extensions`: lower case with the dot (".json"); a file matches without regard to case.
    // None: every file.
    explicit FileBrowser(std::vector<std::string> extensions = {});

    // Lists `folder` (made absolute). False where it cannot be listed: the listing and folder
    // stay, and error() names the folder and the reason.
    bool open(const std::string& folder);
    bool enter(const std::string& name);  // a folder of the listing
    bool up();                            // the parent folder (false at the root)
    bool refresh() { return open(folder_); }
    void setShowHidden(bool show);

    const std::string& folder() const { return folder_; }
    const std::vector<FileEntry>& entries() const { return entries_; }
    const std::string& error() const { return error_; }
    bool showsHidden() const { return showHidden_; }
    bool accepts(const std::string& fileName) const;  // by its extension
    std::string pathOf(const std::string& name) const;
    // The folder and its parents, root first: {label, path} for a row of buttons.
    std::vector<std::pair<std::string, std::string>> crumbs() const;

private:
    std::vector<std::string> extensions_;
    std::string folder_, error_;
    std::vector<FileEntry> entries_;
    bool showHidden_ = false;
};

// Where a dialog about `path` starts: its folder where that exists (or the path itself where it
// is a folder), else the working folder.
std::string startFolder(const std::string& path);
// "12.3 MB": a size for a listing.
std::string sizeText(uintmax_t bytes);

}  // namespace pt::editor
