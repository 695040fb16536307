#include "editor/ui/screenshot.h"

#include <algorithm>
#include <cstdint>
#include <vector>

#include "assets/image/image_write.h"
#include "editor/ui/gl.h"

namespace pt::editor {

void writeWindowScreenshot(const std::string& path, int width, int height) {
    std::vector<uint8_t> bottomUp(size_t(width) * size_t(height) * 3);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadBuffer(GL_BACK);
    glReadPixels(0, 0, width, height, GL_RGB, GL_UNSIGNED_BYTE, bottomUp.data());
    // OpenGL's rows run bottom-up; images are written top row first.
    std::vector<uint8_t> rgb(bottomUp.size());
    const size_t row = size_t(width) * 3;
    for (int y = 0; y < height; ++y) {
        std::copy_n(bottomUp.begin() + std::ptrdiff_t(size_t(height - 1 - y) * row), row,
                    rgb.begin() + std::ptrdiff_t(size_t(y) * row));
    }
    writeDisplayImage(path, uint32_t(width), uint32_t(height), rgb, {{"Software", "pathtracer editor 0.1"}});
}

}  // namespace pt::editor
