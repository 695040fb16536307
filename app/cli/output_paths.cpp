#include "cli/output_paths.h"

#include <cstdio>
#include <filesystem>
#include <stdexcept>

namespace pt::cli {

void checkOutputFolder(const std::string& path) {
    if (path.empty()) return;
    const std::filesystem::path folder = std::filesystem::path(path).parent_path();
    if (!folder.empty() && !std::filesystem::is_directory(folder)) {
        throw std::runtime_error(path + ": folder " + folder.string() + " does not exist");
    }
}

std::string formatFigure(double value) {
    char text[32];
    std::snprintf(text, sizeof text, "%.6g", value);
    return text;
}

}  // namespace pt::cli
