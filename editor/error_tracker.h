#pragma once
// ErrorTracker: the editor's live "error against run time" (DESIGN.md, Error against run time).
// It holds a reference image and, as the accumulation grows, the curve of the mean image's
// error against it (relMSE, RMSE, MAPE; render/util/image_error.h) at logarithmically spaced
// render times, the same figures `pt-render converge` writes, so a user can watch whether an
// edit or a toggle converges to the right answer and how fast.
//
// Thread use: the render thread measures (due() / add()), the UI thread sets the reference
// and reads the curve; every member locks, and the reference is shared, not copied, with
// readers.
#include <cstdint>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

#include "assets/image/reference_image.h"
#include "render/util/error_curve.h"

namespace pt::editor {

class ErrorTracker {
public:
    // Measurements this far apart in render time at least (a factor of 10^(1/8): eight points
    // a decade, as pt-render converge spaces its checkpoints).
    static constexpr double kSpacing = 1.333521432163324;

    // Reads an image file (EXR, PFM, HDR, PNG...) as the reference (loadReferenceImage);
    // throws InputError naming it and keeps the current one.
    void load(const std::string& path);
    void setReference(std::shared_ptr<const ReferenceImage> reference);
    void clear();
    std::shared_ptr<const ReferenceImage> reference() const;

    // The accumulation restarted: the curve starts over.
    void restart();
    // Whether the render thread should measure now: a reference is set, its size is the
    // render's, the render has samples, and (after the first point) `seconds` has grown by
    // kSpacing since the last point. A render whose spp fell below the last point's has
    // restarted: due() then restarts the curve itself.
    bool due(double seconds, uint32_t spp, uint32_t width, uint32_t height);
    // Adds a point for the mean image `beauty` (width x height RGBA) after `seconds`.
    void add(double seconds, uint32_t spp, const std::vector<float>& beauty);

    std::vector<ErrorPoint> curve() const;
    // Why no point is measured ("reference 512x512, render 256x256"), or "".
    std::string problem() const;

private:
    mutable std::mutex mutex_;
    std::shared_ptr<const ReferenceImage> reference_;
    std::vector<ErrorPoint> curve_;
    std::string problem_;
};

}  // namespace pt::editor
