// DisplayProcessor's OpenColorIO constructor (PT_OCIO builds only).
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "assets/color/color_ocio.h"
#include "assets/color/color_processor.h"
#include "assets/input_error.h"

namespace pt {

DisplayProcessor::DisplayProcessor(const ColorConfig& config, const ViewTransform& view, float exposureStops)
    : exposureStops_(exposureStops), configPath_(config.path()), view_(view) {
    const OCIO::ConstProcessorRcPtr processor = ocioDisplayProcessor(config, view);
    OCIO::ConstCPUProcessorRcPtr cpu;
    try {
        cpu =
            processor->getOptimizedCPUProcessor(OCIO::BIT_DEPTH_F32, OCIO::BIT_DEPTH_F32, kOcioOptimization);
    } catch (const OCIO::Exception& e) {
        throw InputError(config.path() + ": " + view.display + " / " + view.view + ": " + e.what());
    }
    // OpenColorIO applies a processor on the calling thread; its CPU processor is immutable,
    // so chunks of the image go to TBB's threads. RGB channel order with a 4-float pixel
    // stride: alpha is neither read nor written.
    ocio_ = [cpu](float* rgba, size_t pixels) {
        constexpr size_t kChunk = 16384;
        tbb::parallel_for(
            tbb::blocked_range<size_t>(0, pixels, kChunk), [&](const tbb::blocked_range<size_t>& r) {
                const ptrdiff_t pixelBytes = 4 * sizeof(float);
                OCIO::PackedImageDesc image(rgba + r.begin() * 4, long(r.size()), 1,
                                            OCIO::CHANNEL_ORDERING_RGB, OCIO::BIT_DEPTH_F32, sizeof(float),
                                            pixelBytes, pixelBytes * ptrdiff_t(r.size()));
                cpu->apply(image);
            });
    };
}

}  // namespace pt
