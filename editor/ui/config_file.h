#pragma once
// Where the editor keeps what it remembers between runs: $XDG_CONFIG_HOME/pathtracer/NAME, else
// ~/.config/pathtracer/NAME.
#include <filesystem>
#include <string>

namespace pt::editor {

std::filesystem::path configFile(const std::string& name);
// Writes `text` there atomically; false where it cannot (a read-only home: what it holds is a
// convenience, kept for this session only).
bool saveConfigFile(const std::string& name, const std::string& text);

}  // namespace pt::editor
