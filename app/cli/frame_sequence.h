#pragma once
// Frame sequences for `pt-render render --frames A:B[:STEP] --fps F` (issue 19): which frames,
// at which times of the animation, written to which files. Frames are independent jobs, so a
// render farm splits a sequence by ranges (--frames 0:99, --frames 100:199, ...) and a
// restarted job skips what is done (--skip-existing).
#include <cstdint>
#include <string>
#include <vector>

namespace pt::cli {

struct FrameRange {
    int64_t first = 0, last = 0, step = 1;  // inclusive; step > 0
    std::vector<int64_t> frames() const;
};

// "A:B" or "A:B:STEP", whole numbers (negative allowed), A <= B, STEP >= 1. Throws UsageError
// naming the flag otherwise.
FrameRange parseFrameRange(const std::string& text);

// `pattern` with its run of '#' replaced by `frame`, zero-padded to the run's length
// ("out_####.exr", 7 -> "out_0007.exr"; a negative frame keeps its sign: "out_-007.exr").
// Throws UsageError where the pattern has no '#' run, or more than one.
std::string framePath(const std::string& pattern, int64_t frame);
bool hasFrameNumber(const std::string& pattern);

}  // namespace pt::cli
