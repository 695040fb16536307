#include "editor/edit_labels.h"

#include <vector>

#include "render/backend/aov.h"
#include "render/backend/toggle_table.h"

namespace pt::editor {
namespace {

// "<what>: a, b" for the fields that changed; "<what>" where none of those named did.
class Label {
public:
    explicit Label(std::string what) : what_(std::move(what)) {}
    template <typename T>
    Label& field(const char* name, const T& before, const T& after) {
        if (!(before == after)) fields_.push_back(name);
        return *this;
    }
    Label& onOff(const char* name, bool before, bool after) {
        if (before != after) fields_.push_back(std::string(name) + (after ? " on" : " off"));
        return *this;
    }
    Label& text(bool changed, std::string text) {
        if (changed) fields_.push_back(std::move(text));
        return *this;
    }
    std::string str() const {
        std::string s = what_;
        for (size_t i = 0; i < fields_.size(); ++i) s += (i == 0 ? ": " : ", ") + fields_[i];
        return s;
    }

private:
    std::string what_;
    std::vector<std::string> fields_;
};

bool sameVec(Vec3 a, Vec3 b) { return a.x == b.x && a.y == b.y && a.z == b.z; }

}  // namespace

std::string cameraEditLabel(const Camera& before, const Camera& after) {
    return Label("Camera")
        .text(!sameVec(before.position, after.position), "position")
        .text(!sameVec(before.lookAt, after.lookAt), "look at")
        .text(!sameVec(before.up, after.up), "up")
        .field("field of view", before.verticalFovDegrees, after.verticalFovDegrees)
        .field("aperture", before.apertureRadius, after.apertureRadius)
        .field("focus distance", before.focusDistance, after.focusDistance)
        .str();
}

std::string renderSettingsEditLabel(const RenderSettings& before, const RenderSettings& after) {
    return Label("Render settings")
        .text(before.width != after.width || before.height != after.height,
              "resolution " + std::to_string(after.width) + "x" + std::to_string(after.height))
        .text(before.maxDepth != after.maxDepth, "max depth " + std::to_string(after.maxDepth))
        .field("spp", before.spp, after.spp)
        .field("seed", before.seed, after.seed)
        .str();
}

std::string togglesEditLabel(const IntegratorToggles& before, const IntegratorToggles& after) {
    Label label("Renderer");
    for (const ToggleRow& row : toggleTable()) label.onOff(row.editLabel, row.get(before), row.get(after));
    return label.field("firefly clamp", before.clampRadiance, after.clampRadiance)
        .field("kernel variant", before.kernelVariant, after.kernelVariant)
        .field("rebuild ratio", before.rebuildSahRatio, after.rebuildSahRatio)
        .str();
}

std::string viewerEditLabel(const ViewerSettings& before, const ViewerSettings& after) {
    const DisplaySettings &b = before.display, &a = after.display;
    return Label("Display")
        .text(before.aov != after.aov,
              after.aov < 0 ? std::string("beauty") : "AOV " + std::string(aovName(Aov(after.aov))))
        .onOff("denoise", before.denoise, after.denoise)
        .field("exposure", b.exposureStops, a.exposureStops)
        .field("tone mapper", b.toneMapper, a.toneMapper)
        .field("white point", b.whitePoint, a.whitePoint)
        .onOff("dither", b.dither, a.dither)
        .onOff("built-in operators", before.builtinDisplay, after.builtinDisplay)
        .field("samples per frame", before.samplesPerFrame, after.samplesPerFrame)
        .field("stop at spp", before.targetSpp, after.targetSpp)
        .field("export layers", before.exportAovs, after.exportAovs)
        .onOff("half-float export", before.exportHalf, after.exportHalf)
        .onOff("follow the viewport", before.followViewport, after.followViewport)
        .field("resolution scale", before.resolutionScale, after.resolutionScale)
        .str();
}

std::string environmentEditLabel(const Environment& before, const Environment& after) {
    return Label("Environment")
        .text(!sameVec(before.color, after.color), "colour")
        .text(before.texture != after.texture && after.texture < 0, "no image")
        .field("strength", before.intensity, after.intensity)
        .field("rotation", before.rotationDegrees, after.rotationDegrees)
        .str();
}

}  // namespace pt::editor
