#pragma once
// Screenshots of the whole window (panels included), as PNG, for automation and tests.
#include <string>

namespace pt::editor {

// Reads the current back buffer (framebufferWidth x framebufferHeight) and writes it
// atomically. Throws InputError naming the path on failure.
void writeWindowScreenshot(const std::string& path, int framebufferWidth, int framebufferHeight);

}  // namespace pt::editor
