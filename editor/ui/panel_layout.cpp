#include "editor/ui/panel_layout.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>

#include "editor/ui/config_file.h"

namespace pt::editor {
namespace {

constexpr const char* kLayoutFile = "layout.txt";

}  // namespace

float PanelLayout::clampedWidth(float windowWidth) const {
    const float lo = kMinWidth * scale, hi = std::max(lo, windowWidth - kMinViewport * scale);
    return std::clamp(width, lo, hi);
}

std::string PanelLayout::serialize() const {
    std::ostringstream out;
    out << "panel_width " << std::lround(width / scale) << "\n";
    out << "stats_overlay " << (statsOverlay ? 1 : 0) << "\n";
    return out.str();
}

PanelLayout PanelLayout::parse(const std::string& text, float scale) {
    PanelLayout layout;
    layout.scale = scale;
    layout.width = kDefaultWidth * scale;
    std::istringstream in(text);
    std::string key;
    float value = 0.0f;
    while (in >> key >> value) {
        if (key == "panel_width" && std::isfinite(value) && value >= kMinWidth && value <= 4096.0f)
            layout.width = value * scale;
        if (key == "stats_overlay") layout.statsOverlay = value == 1.0f;
    }
    return layout;
}

PanelLayout loadPanelLayout(float scale) {
    std::ifstream in(configFile(kLayoutFile));
    std::ostringstream text;
    text << in.rdbuf();
    return PanelLayout::parse(text.str(), scale);
}

void savePanelLayout(const PanelLayout& layout) { saveConfigFile(kLayoutFile, layout.serialize()); }

}  // namespace pt::editor
