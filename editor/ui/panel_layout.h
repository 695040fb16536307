#pragma once
// The panels' column: its width, which the user drags at its left edge and the editor
// remembers between runs (with whether the Stats overlay is shown and which panels float)
// ($XDG_CONFIG_HOME/pathtracer/layout.txt), and the scale of the whole interface on a high-DPI screen (GLFW's
// content scale: fonts and sizes grow with it).
#include <string>
#include <vector>

namespace pt::editor {

// The panels, in the column's order (their headers' names).
constexpr const char* kPanelNames[] = {"Outliner",    "Inspector", "Camera",    "Render settings",
                                       "Environment", "Display",   "Animation", "Stats"};
constexpr int kPanelCount = int(sizeof(kPanelNames) / sizeof(kPanelNames[0]));

struct PanelLayout {
    static constexpr float kDefaultWidth = 400.0f;  // at scale 1
    static constexpr float kMinWidth = 260.0f;
    static constexpr float kMinViewport = 160.0f;  // what the column leaves the viewport at least

    float width = kDefaultWidth;
    float scale = 1.0f;
    bool resizing = false;      // the user is dragging the column's edge
    bool statsOverlay = false;  // the Stats figures over the viewport (the toolbar's "Stats")
    // Panels taken out of the column into windows of their own (Window menu); closing such a
    // window puts the panel back.
    std::vector<std::string> floating;
    bool floats(const std::string& panel) const;
    void setFloating(const std::string& panel, bool on);

    // The width kept within [kMinWidth, window - kMinViewport] (scaled).
    float clampedWidth(float windowWidth) const;
    // "panel_width 400\nstats_overlay 0\nfloating Display\n...", unscaled
    std::string serialize() const;
    static PanelLayout parse(const std::string& text, float scale);  // defaults where absent
};

PanelLayout loadPanelLayout(float scale);
void savePanelLayout(const PanelLayout& layout);  // ignores a read-only home

}  // namespace pt::editor
