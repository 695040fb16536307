// Display: what the viewport shows (the beauty or one AOV) and how (exposure, tone mapper).
// Display changes never restart accumulation; switching the AOV starts accumulating that AOV
// beside the beauty's samples.
#include <cstdio>
#include <string>
#include <vector>

#include "editor/auto_exposure.h"
#include "editor/scene_edits.h"
#include "editor/ui/widgets.h"

namespace pt::editor {

namespace {

// Display > Reference image: the image the Stats panel measures the error against, and the
// A/B switch between the render, the reference and their difference.
void drawReference(EditorUi& ui) {
    ImGui::Separator();
    ImGui::TextUnformatted("Reference image");
    static char path[1024] = "";  // the field's text; starts as --reference's path
    if (path[0] == '\0' && !ui.referencePath.empty()) {
        std::snprintf(path, sizeof path, "%s", ui.referencePath.c_str());
    }
    ImGui::InputText("##reference path", path, sizeof path);
    ImGui::SameLine();
    if (ImGui::Button("Load")) ui.loadReference(path);
    const auto reference = ui.worker.errors().reference();
    if (!reference) {
        ImGui::TextDisabled("EXR, HDR or PNG, e.g. from pt-render reference");
        return;
    }
    ImGui::SameLine();
    if (ImGui::Button("Clear")) {
        ui.worker.errors().clear();
        ui.compare = CompareView::Render;
        return;
    }
    ImGui::Text("%ux%u%s", reference->width, reference->height,
                reference->noiseRelMse > 0.0 ? "" : " (no noise estimate in its metadata)");
    int compare = int(ui.compare);
    ImGui::RadioButton("Render (A)", &compare, int(CompareView::Render));
    ImGui::SameLine();
    ImGui::RadioButton("Reference (B)", &compare, int(CompareView::Reference));
    ImGui::SameLine();
    ImGui::RadioButton("|A - B|", &compare, int(CompareView::Difference));
    ui.compare = CompareView(compare);
    if (ui.doc().viewer.aov >= 0) ImGui::TextDisabled("The comparison shows with the beauty, not an AOV.");
}

#ifdef PT_HAVE_OCIO
// One combo over `names` ("" shows as `none`, when given); true when the choice changed.
bool comboOfNames(const char* label, std::string& value, const std::vector<std::string>& names,
                  const char* none = nullptr) {
    bool changed = false;
    const bool open = ImGui::BeginCombo(label, value.empty() && none ? none : value.c_str());
    if (!open) {
        tooltipIfCut(label);
        return false;
    }
    if (none && ImGui::Selectable(none, value.empty())) value.clear(), changed = true;
    for (const std::string& name : names) {
        if (ImGui::Selectable(name.c_str(), name == value)) value = name, changed = true;
    }
    ImGui::EndCombo();
    return changed;
}

// The scene's OpenColorIO choice (saved with it): the config and its display, view and look.
void drawColorView(EditorUi& ui, const ColorView& color) {
    ColorSettings c = ui.doc().scene.color;
    // The resolved names, so the combos show what is drawn even where the scene left defaults.
    ViewTransform shown = color.view;
    bool changed = comboOfNames("Display", shown.display, color.config->displays());
    if (changed) shown.view.clear();  // the new display's default view
    changed |= comboOfNames("View", shown.view, color.config->views(shown.display));
    changed |= comboOfNames("Look", shown.look, color.config->looks(), "None");
    if (changed) {
        c.display = shown.display, c.view = shown.view, c.look = shown.look;
        ui.apply(setColorSettings(ui.doc(), c));
    }
    static char path[1024] = "";  // the config field; starts as the config in use
    if (path[0] == '\0') std::snprintf(path, sizeof path, "%s", color.config->path().c_str());
    ImGui::InputText("##config", path, sizeof path);
    ImGui::SameLine();
    if (ImGui::Button("Use config")) {
        c.config = path;
        c.display = c.view = c.look = "";  // names of the old config mean nothing in the new one
        ui.apply(setColorSettings(ui.doc(), c));
    }
    if (!ui.options.ocioPath.empty()) ImGui::TextDisabled("--ocio overrides the scene's config");
}
#else
// Without OpenColorIO (PT_OCIO=OFF) a ColorView never has a config (color_view.cpp), and
// ColorConfig is not built: nothing to draw.
void drawColorView(EditorUi&, const ColorView&) {}
#endif

}  // namespace

void drawDisplayPanel(EditorUi& ui, const DisplayView& view) {
    if (!ImGui::CollapsingHeader("Display", ImGuiTreeNodeFlags_DefaultOpen)) return;
    ViewerSettings v = ui.doc().viewer;
    bool changed = false;
    const std::string current = v.aov < 0 ? "beauty" : aovName(Aov(v.aov));
    const bool aovOpen = ImGui::BeginCombo("AOV", current.c_str());
    if (!aovOpen) tooltipIfCut("AOV");
    if (aovOpen) {
        if (ImGui::Selectable("beauty", v.aov < 0)) v.aov = -1, changed = true;
        for (int32_t a = 0; a < int32_t(Aov::Count); ++a) {
            if (ImGui::Selectable(aovName(Aov(a)), v.aov == a)) v.aov = a, changed = true;
        }
        ImGui::EndCombo();
    }
    // Turning it on restarts the accumulation once, for the guides; after that it is a display switch.
    changed |= checkbox("Denoise (a-trous, guided by albedo, normal, depth)", &v.denoise);
    // [Auto][slider] Exposure: the button before the slider, so the label stays in its column.
    const float autoWidth = ImGui::CalcTextSize("Auto").x + 2.0f * ImGui::GetStyle().FramePadding.x;
    const float sliderWidth = ImGui::CalcItemWidth() - autoWidth - ImGui::GetStyle().ItemInnerSpacing.x;
    if (ImGui::Button("Auto")) {  // the frame's log-average luminance to middle grey
        std::vector<float> beauty;
        ui.worker.withBackend([&](EditorSession& s) { s.backend().readBeauty(beauty); });
        v.display.exposureStops = autoExposureStops(beauty);
        changed = true;
    }
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip("Bring the render's log-average luminance to middle grey (0.18)");
    ImGui::SameLine(0.0f, ImGui::GetStyle().ItemInnerSpacing.x);
    ImGui::SetNextItemWidth(sliderWidth);
    changed |= sliderFloat(ui, "Exposure (stops)", &v.display.exposureStops, -16.0f, 16.0f, "%.2f");
    const ColorView& color = ui.colorView;
    if (color.config) {
        bool ocio = !v.builtinDisplay;
        if (checkbox("OpenColorIO view", &ocio)) v.builtinDisplay = !ocio, changed = true;
    }
    if (color.config && !v.builtinDisplay) {
        drawColorView(ui, color);
    } else {
        int op = int(v.display.toneMapper);
        const bool picked = ImGui::Combo("Tone mapper", &op, "Standard (sRGB)\0Reinhard\0ACES fitted\0AgX\0");
        tooltipIfCut("Tone mapper");
        if (picked) {
            v.display.toneMapper = ToneMapper(op);
            changed = true;
        }
        if (v.display.toneMapper == ToneMapper::Reinhard) {
            changed |= sliderFloat(ui, "White point", &v.display.whitePoint, 0.1f, 100.0f, "%.2f",
                                   ImGuiSliderFlags_Logarithmic);
        }
    }
    changed |= checkbox("Dither", &v.display.dither);
    if (!color.error.empty()) ImGui::TextColored(ImVec4(1, 0.6f, 0.3f, 1), "%s", color.error.c_str());
    if (!view.shaderError().empty()) {
        ImGui::TextColored(ImVec4(1, 0.4f, 0.4f, 1), "Built-in operators shown: %s",
                           view.shaderError().c_str());
    }
    if (changed) ui.apply(setViewer(ui.doc(), v));
    if (v.aov >= 0) {
        const Aov aov = Aov(v.aov);
        if (aov == Aov::Depth || aov == Aov::BvhCost || aov == Aov::SampleCount || aov == Aov::Variance) {
            // The heat map's legend: black at 0 through blue, green and yellow to red at the maximum.
            ImGui::Text("Heat map: 0 (black) ... %.4g (red)", double(view.aovMaximum()));
        } else if (aov == Aov::InstanceId || aov == Aov::MaterialId) {
            ImGui::TextDisabled("False colours; exact ids are in exported EXRs.");
        }
    }
    drawReference(ui);
}

}  // namespace pt::editor
