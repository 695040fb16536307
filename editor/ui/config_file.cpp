#include "editor/ui/config_file.h"

#include <cstdlib>

#include "assets/atomic_file.h"

namespace pt::editor {

std::filesystem::path configFile(const std::string& name) {
    if (const char* xdg = std::getenv("XDG_CONFIG_HOME"); xdg && *xdg) {
        return std::filesystem::path(xdg) / "pathtracer" / name;
    }
    const char* home = std::getenv("HOME");
    return std::filesystem::path(home ? home : ".") / ".config" / "pathtracer" / name;
}

bool saveConfigFile(const std::string& name, const std::string& text) {
    try {
        std::filesystem::create_directories(configFile(name).parent_path());
        writeTextAtomically(configFile(name).string(), text);
        return true;
    } catch (const std::exception&) {
        return false;
    }
}

}  // namespace pt::editor
