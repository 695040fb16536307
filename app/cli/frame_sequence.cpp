#include "cli/frame_sequence.h"

#include <cstdlib>

#include "cli/cli_options.h"

namespace pt::cli {
namespace {

int64_t wholeNumber(const std::string& text, const std::string& whole) {
    char* end = nullptr;
    const long long value = std::strtoll(text.c_str(), &end, 10);
    if (text.empty() || *end != '\0') {
        throw UsageError("--frames " + whole + ": \"" + text +
                         "\" is not a whole number (expected A:B or A:B:STEP)");
    }
    return int64_t(value);
}

}  // namespace

std::vector<int64_t> FrameRange::frames() const {
    std::vector<int64_t> out;
    for (int64_t f = first; f <= last; f += step) out.push_back(f);
    return out;
}

FrameRange parseFrameRange(const std::string& text) {
    std::vector<std::string> parts(1);
    for (const char c : text) {
        if (c == ':') {
            parts.emplace_back();
        } else {
            parts.back() += c;
        }
    }
    if (parts.size() < 2 || parts.size() > 3) {
        throw UsageError("--frames " + text + ": expected A:B or A:B:STEP");
    }
    FrameRange range;
    range.first = wholeNumber(parts[0], text);
    range.last = wholeNumber(parts[1], text);
    if (parts.size() == 3) range.step = wholeNumber(parts[2], text);
    if (range.last < range.first)
        throw UsageError("--frames " + text + ": the last frame is before the first");
    if (range.step < 1) throw UsageError("--frames " + text + ": the step must be at least 1");
    return range;
}

bool hasFrameNumber(const std::string& pattern) { return pattern.find('#') != std::string::npos; }

std::string framePath(const std::string& pattern, int64_t frame) {
    const size_t start = pattern.find('#');
    if (start == std::string::npos)
        throw UsageError(pattern + ": a sequence's file names need #### for the frame");
    size_t end = start;
    while (end < pattern.size() && pattern[end] == '#') ++end;
    if (pattern.find('#', end) != std::string::npos) {
        throw UsageError(pattern + ": one run of # stands for the frame number; this has more");
    }
    std::string digits = std::to_string(frame < 0 ? -frame : frame);
    const size_t width = end - start - (frame < 0 ? 1 : 0);
    if (digits.size() < width) digits.insert(0, width - digits.size(), '0');
    if (frame < 0) digits.insert(0, 1, '-');
    return pattern.substr(0, start) + digits + pattern.substr(end);
}

}  // namespace pt::cli
