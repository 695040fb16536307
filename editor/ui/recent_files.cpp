#include "editor/ui/recent_files.h"

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>

#include "assets/atomic_file.h"

namespace pt::editor {
namespace {

constexpr size_t kMaxRecent = 10;

std::filesystem::path recentFilePath() {
    if (const char* xdg = std::getenv("XDG_CONFIG_HOME"); xdg && *xdg) {
        return std::filesystem::path(xdg) / "pathtracer" / "recent.txt";
    }
    const char* home = std::getenv("HOME");
    return std::filesystem::path(home ? home : ".") / ".config" / "pathtracer" / "recent.txt";
}

}  // namespace

std::vector<std::string> loadRecentFiles() {
    std::vector<std::string> files;
    std::ifstream in(recentFilePath());
    for (std::string line; std::getline(in, line) && files.size() < kMaxRecent;) {
        if (!line.empty()) files.push_back(line);
    }
    return files;
}

std::vector<std::string> rememberRecentFile(std::vector<std::string> files, const std::string& path) {
    files.erase(std::remove(files.begin(), files.end(), path), files.end());
    files.insert(files.begin(), path);
    if (files.size() > kMaxRecent) files.resize(kMaxRecent);
    std::string text;
    for (const std::string& f : files) text += f + "\n";
    try {
        std::filesystem::create_directories(recentFilePath().parent_path());
        writeTextAtomically(recentFilePath().string(), text);
    } catch (const std::exception&) {
        // A read-only home: the list still works for this session.
    }
    return files;
}

}  // namespace pt::editor
