#include "editor/ui/error_plot.h"

#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace pt::editor {
namespace {

// Whole decades covering [lo, hi] (both > 0), at least one decade wide.
void decadeRange(double lo, double hi, double& first, double& last) {
    first = std::floor(std::log10(lo));
    last = std::ceil(std::log10(hi));
    if (last <= first) last = first + 1.0;
}

}  // namespace

void drawErrorPlot(const std::vector<ErrorPoint>& curve, double referenceNoiseRelMse, float height) {
    std::vector<ErrorPoint> points;
    for (const ErrorPoint& p : curve) {
        if (p.seconds > 0.0 && p.error.relMse > 0.0) points.push_back(p);  // a log axis shows only these
    }
    if (points.empty()) {
        ImGui::TextDisabled("Measuring...");
        return;
    }
    double x0, x1, y0, y1;
    decadeRange(points.front().seconds, points.back().seconds, x0, x1);
    double lowest = points.front().error.relMse, highest = lowest;
    for (const ErrorPoint& p : points)
        lowest = std::min(lowest, p.error.relMse), highest = std::max(highest, p.error.relMse);
    if (referenceNoiseRelMse > 0.0) lowest = std::min(lowest, referenceNoiseRelMse);
    decadeRange(lowest, highest, y0, y1);

    const float labelWidth = ImGui::CalcTextSize("1e-10").x + 4.0f;
    const ImVec2 origin = ImGui::GetCursorScreenPos();
    const float width = std::max(ImGui::GetContentRegionAvail().x, 120.0f);
    const ImVec2 a(origin.x + labelWidth, origin.y), b(origin.x + width, origin.y + height);
    const auto toScreen = [&](double seconds, double relMse) {
        const double u = (std::log10(seconds) - x0) / (x1 - x0), v = (std::log10(relMse) - y0) / (y1 - y0);
        return ImVec2(a.x + float(u) * (b.x - a.x), b.y - float(v) * (b.y - a.y));
    };
    ImDrawList* draw = ImGui::GetWindowDrawList();
    const ImU32 grid = IM_COL32(90, 90, 90, 255), text = ImGui::GetColorU32(ImGuiCol_TextDisabled);
    draw->AddRectFilled(a, b, IM_COL32(20, 20, 24, 255));
    char label[32];
    for (double d = y0; d <= y1; d += 1.0) {
        const float y = toScreen(std::pow(10.0, x0), std::pow(10.0, d)).y;
        draw->AddLine(ImVec2(a.x, y), ImVec2(b.x, y), grid);
        std::snprintf(label, sizeof label, "1e%d", int(d));
        draw->AddText(ImVec2(origin.x, y - ImGui::GetFontSize() * 0.5f), text, label);
    }
    for (double d = x0; d <= x1; d += 1.0) {
        const float x = toScreen(std::pow(10.0, d), std::pow(10.0, y0)).x;
        draw->AddLine(ImVec2(x, a.y), ImVec2(x, b.y), grid);
    }
    draw->PushClipRect(a, b, true);
    if (referenceNoiseRelMse > 0.0) {
        const float y = toScreen(std::pow(10.0, x0), referenceNoiseRelMse).y;
        draw->AddLine(ImVec2(a.x, y), ImVec2(b.x, y), IM_COL32(200, 120, 60, 255), 1.0f);
    }
    // The guide: relMSE proportional to 1 / time, through the first point.
    const ErrorPoint& first = points.front();
    const double guideEnd = std::pow(10.0, x1);
    draw->AddLine(toScreen(first.seconds, first.error.relMse),
                  toScreen(guideEnd, first.error.relMse * first.seconds / guideEnd),
                  IM_COL32(120, 120, 120, 255));
    std::vector<ImVec2> line;
    for (const ErrorPoint& p : points) line.push_back(toScreen(p.seconds, p.error.relMse));
    draw->AddPolyline(line.data(), int(line.size()), IM_COL32(90, 200, 255, 255), 0, 2.0f);
    for (const ImVec2& q : line) draw->AddCircleFilled(q, 2.5f, IM_COL32(90, 200, 255, 255));
    draw->PopClipRect();

    ImGui::InvisibleButton("##error plot", ImVec2(width, height));
    if (ImGui::IsItemHovered()) {
        // The point nearest the mouse in x.
        const float mouse = ImGui::GetIO().MousePos.x;
        size_t nearest = 0;
        for (size_t i = 1; i < line.size(); ++i) {
            if (std::fabs(line[i].x - mouse) < std::fabs(line[nearest].x - mouse)) nearest = i;
        }
        const ErrorPoint& p = points[nearest];
        ImGui::SetTooltip("%.3g s, %u spp\nrelMSE %.3g\nRMSE %.3g\nMAPE %.2f%%", p.seconds, p.spp,
                          p.error.relMse, p.error.rmse, p.error.mape);
    }
    ImGui::TextDisabled("time %.0e .. %.0e s; grey: slope -1%s", std::pow(10.0, x0), std::pow(10.0, x1),
                        referenceNoiseRelMse > 0.0 ? "; orange: the reference's noise" : "");
}

}  // namespace pt::editor
