#pragma once
// The File menu's recent files, kept in $XDG_CONFIG_HOME/pathtracer/recent.txt (else
// ~/.config/...), one absolute path per line, newest first, at most ten.
#include <string>
#include <vector>

namespace pt::editor {

std::vector<std::string> loadRecentFiles();
// Moves `path` to the front and saves the list (atomically; a failure to save is ignored:
// the list is a convenience). Returns the new list.
std::vector<std::string> rememberRecentFile(std::vector<std::string> files, const std::string& path);

}  // namespace pt::editor
