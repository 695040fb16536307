#include "cli/guide_samples.h"

#include "cli/cli_options.h"

namespace pt::cli {

uint32_t parseGuideSamples(const std::string& flag, const std::string& value) {
    if (value == "all") return 0;
    const bool digits =
        !value.empty() && value.size() <= 9 && value.find_first_not_of("0123456789") == std::string::npos;
    const uint32_t samples = digits ? uint32_t(std::stoul(value)) : 0;
    if (samples == 0)
        throw UsageError(flag + ": expected a positive number of samples or \"all\", got \"" + value + "\"");
    return samples;
}

}  // namespace pt::cli
