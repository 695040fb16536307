#pragma once
// A progress bar with an ETA on stderr, drawn only when stderr is a terminal (and not with
// --quiet), so logs and pipes stay clean.
#include <chrono>
#include <string>

#include "render/util/progress.h"

namespace pt::cli {

class ProgressBar {
public:
    explicit ProgressBar(bool enabled);
    ~ProgressBar();

    // fraction in [0, 1]; redraws at most ~10 times a second.
    void update(const std::string& stage, double fraction);
    void finish();  // clears the line
    ProgressFn callback();

private:
    bool enabled_;
    bool drawn_ = false;
    std::string stage_;
    std::chrono::steady_clock::time_point stageStart_, lastDraw_;
};

std::string formatDuration(double seconds);

}  // namespace pt::cli
