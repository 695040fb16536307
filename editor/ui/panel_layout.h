#pragma once
// The panels' column: its width, which the user drags at its left edge and the editor
// remembers between runs (with whether the Stats overlay is shown) ($XDG_CONFIG_HOME/pathtracer/layout.txt),
// and the scale of the whole interface on a high-DPI screen (GLFW's content scale: fonts and sizes grow with
// it).
#include <string>

namespace pt::editor {

struct PanelLayout {
    static constexpr float kDefaultWidth = 400.0f;  // at scale 1
    static constexpr float kMinWidth = 260.0f;
    static constexpr float kMinViewport = 160.0f;  // what the column leaves the viewport at least

    float width = kDefaultWidth;
    float scale = 1.0f;
    bool resizing = false;  // the user is dragging the column's edge
    bool statsOverlay = false;  // the Stats figures over the viewport (the toolbar's "Stats")

    // The width kept within [kMinWidth, window - kMinViewport] (scaled).
    float clampedWidth(float windowWidth) const;
    std::string serialize() const;  // "panel_width 400\nstats_overlay 0\n", unscaled
    static PanelLayout parse(const std::string& text, float scale);  // defaults where absent
};

PanelLayout loadPanelLayout(float scale);
void savePanelLayout(const PanelLayout& layout);  // ignores a read-only home

}  // namespace pt::editor
