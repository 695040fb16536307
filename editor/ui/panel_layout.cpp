#include "editor/ui/panel_layout.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <iterator>
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
    for (const std::string& panel : floating) out << "floating " << panel << "\n";
    return out.str();
}

PanelLayout PanelLayout::parse(const std::string& text, float scale) {
    PanelLayout layout;
    layout.scale = scale;
    layout.width = kDefaultWidth * scale;
    std::istringstream lines(text);
    std::string line;
    while (std::getline(lines, line)) {
        std::istringstream in(line);
        std::string key, rest;
        in >> key;
        std::getline(in >> std::ws, rest);
        if (key == "floating") {
            const auto known = std::find(std::begin(kPanelNames), std::end(kPanelNames), rest);
            if (known != std::end(kPanelNames)) layout.setFloating(rest, true);
            continue;
        }
        char* end = nullptr;
        const float value = std::strtof(rest.c_str(), &end);
        if (rest.empty() || end == rest.c_str()) continue;
        if (key == "panel_width" && std::isfinite(value) && value >= kMinWidth && value <= 4096.0f)
            layout.width = value * scale;
        if (key == "stats_overlay") layout.statsOverlay = value == 1.0f;
    }
    return layout;
}

bool PanelLayout::floats(const std::string& panel) const {
    return std::find(floating.begin(), floating.end(), panel) != floating.end();
}

void PanelLayout::setFloating(const std::string& panel, bool on) {
    floating.erase(std::remove(floating.begin(), floating.end(), panel), floating.end());
    if (on) floating.push_back(panel);
}

PanelLayout loadPanelLayout(float scale) {
    std::ifstream in(configFile(kLayoutFile));
    std::ostringstream text;
    text << in.rdbuf();
    return PanelLayout::parse(text.str(), scale);
}

void savePanelLayout(const PanelLayout& layout) { saveConfigFile(kLayoutFile, layout.serialize()); }

}  // namespace pt::editor
