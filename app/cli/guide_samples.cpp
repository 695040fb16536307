#include "cli/guide_samples.h"

namespace pt::cli {

uint32_t guideSamplesOption(const Options& o) {
    const std::optional<std::string> value = o.value("--guide-samples");
    if (!value) return kSettledGuideSamples;
    return *value == "all" ? 0u : *o.positiveInt("--guide-samples");
}

}  // namespace pt::cli
