#pragma once
// Small helpers for commands that write result files.
#include <string>

namespace pt::cli {

// Throws std::runtime_error naming `path` when its folder does not exist, so that a command
// fails before it spends minutes rendering rather than after. An empty path is ignored.
void checkOutputFolder(const std::string& path);

// A measured figure as text with 6 significant digits ("0.0123457", "1.5e-07"), for CSV
// cells and image attributes.
std::string formatFigure(double value);

}  // namespace pt::cli
