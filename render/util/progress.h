#pragma once
// Progress reporting for long host operations (loading, BVH builds, offline renders). The
// CLI turns reports into a progress bar with an ETA; the editor into a progress widget.
#include <functional>
#include <string>

namespace pt {

// Called with the stage's name and the fraction of it done, in [0, 1]. May be empty.
using ProgressFn = std::function<void(const std::string& stage, double fraction)>;

inline void reportProgress(const ProgressFn& progress, const std::string& stage, double fraction) {
    if (progress) progress(stage, fraction);
}

}  // namespace pt
