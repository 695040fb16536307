#include "cli/progress_bar.h"

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace pt::cli {

ProgressBar::ProgressBar(bool enabled) : enabled_(enabled && ::isatty(STDERR_FILENO)) {}

ProgressBar::~ProgressBar() { finish(); }

std::string formatDuration(double seconds) {
    char buf[32];
    if (!std::isfinite(seconds) || seconds < 0) return "--";
    if (seconds < 60)
        std::snprintf(buf, sizeof buf, "%.0fs", std::ceil(seconds));
    else if (seconds < 3600)
        std::snprintf(buf, sizeof buf, "%dm%02ds", int(seconds) / 60, int(seconds) % 60);
    else
        std::snprintf(buf, sizeof buf, "%dh%02dm", int(seconds) / 3600, (int(seconds) / 60) % 60);
    return buf;
}

void ProgressBar::update(const std::string& stage, double fraction) {
    if (!enabled_) return;
    const auto now = std::chrono::steady_clock::now();
    if (stage != stage_) {
        stage_ = stage;
        stageStart_ = now;
    } else if (fraction < 1.0 && now - lastDraw_ < std::chrono::milliseconds(100)) {
        return;
    }
    lastDraw_ = now;
    fraction = std::clamp(fraction, 0.0, 1.0);
    const double elapsed = std::chrono::duration<double>(now - stageStart_).count();
    const double eta = fraction > 0.0 ? elapsed * (1.0 - fraction) / fraction : -1.0;
    constexpr int kWidth = 30;
    const int filled = int(fraction * kWidth);
    std::string bar(size_t(filled), '#');
    bar.resize(kWidth, '-');
    std::fprintf(stderr, "\r\033[K%-12s [%s] %3d%%  %s elapsed  ETA %s", stage.c_str(), bar.c_str(),
                 int(fraction * 100.0), formatDuration(elapsed).c_str(), formatDuration(eta).c_str());
    std::fflush(stderr);
    drawn_ = true;
}

void ProgressBar::finish() {
    if (drawn_) {
        std::fprintf(stderr, "\r\033[K");
        std::fflush(stderr);
        drawn_ = false;
    }
}

ProgressFn ProgressBar::callback() {
    return [this](const std::string& stage, double fraction) { update(stage, fraction); };
}

}  // namespace pt::cli
