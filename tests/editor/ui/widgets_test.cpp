// Labels cut at the panel's edge (editor/ui/widgets.h, tooltipIfCut): hovering a widget whose
// label runs past the window's right edge shows the whole label in a tooltip; a label that fits
// shows none. Dear ImGui runs here without a window or GL: frames are laid out, not drawn.
#include "editor/ui/widgets.h"

#include <gtest/gtest.h>
#include <imgui_internal.h>

namespace pt::editor {
namespace {

class HeadlessImGui : public ::testing::Test {
protected:
    void SetUp() override {
        ImGui::CreateContext();
        ImGuiIO& io = ImGui::GetIO();
        io.IniFilename = nullptr;
        io.DisplaySize = ImVec2(1200.0f, 400.0f);
        io.DeltaTime = 1.0f / 60.0f;
        unsigned char* pixels = nullptr;
        int w = 0, h = 0;
        io.Fonts->GetTexDataAsRGBA32(&pixels, &w, &h);  // the default 13 px font, as the editor's
    }
    void TearDown() override { ImGui::DestroyContext(); }

    // A slider labelled `label` in a window `width` wide at the origin, the pointer on its frame
    // for a few frames; whether a tooltip was up in the last.
    bool tooltipShown(float width, const char* label) {
        ImGui::GetIO().MousePos = ImVec2(20.0f, 15.0f);
        bool shown = false;
        for (int frame = 0; frame < 3; ++frame) {
            ImGui::NewFrame();
            ImGui::SetNextWindowPos(ImVec2(0.0f, 0.0f));
            ImGui::SetNextWindowSize(ImVec2(width, 100.0f));
            ImGui::Begin("panel", nullptr, ImGuiWindowFlags_NoDecoration);
            float value = 0.5f;
            ImGui::SliderFloat(label, &value, 0.0f, 1.0f);
            tooltipIfCut(label);
            ImGui::End();
            const ImGuiWindow* tip = ImGui::FindWindowByName("##Tooltip_00");
            shown = tip && tip->Active;
            ImGui::Render();
        }
        return shown;
    }
};

TEST_F(HeadlessImGui, ACutLabelShowsItselfInATooltip) {
    // 400 wide: the frame takes 65% (260 px), "Clearcoat roughness" (133 px) runs past the edge.
    EXPECT_TRUE(tooltipShown(400.0f, "Clearcoat roughness"));
    EXPECT_TRUE(tooltipShown(400.0f, "Clearcoat roughness##material 3")) << "the hidden id is no part of it";
}

TEST_F(HeadlessImGui, ALabelThatFitsShowsNoTooltip) {
    EXPECT_FALSE(tooltipShown(400.0f, "IOR"));
    EXPECT_FALSE(tooltipShown(700.0f, "Clearcoat roughness")) << "a wider column has room for it";
}

}  // namespace
}  // namespace pt::editor
