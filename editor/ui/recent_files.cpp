#include "editor/ui/recent_files.h"

#include <algorithm>
#include <fstream>

#include "editor/ui/config_file.h"

namespace pt::editor {
namespace {

constexpr size_t kMaxRecent = 10;
constexpr const char* kRecentFile = "recent.txt";

}  // namespace

std::vector<std::string> loadRecentFiles() {
    std::vector<std::string> files;
    std::ifstream in(configFile(kRecentFile));
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
    saveConfigFile(kRecentFile, text);  // a read-only home: the list still works for this session
    return files;
}

}  // namespace pt::editor
