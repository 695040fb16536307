#pragma once
// BenchReport: the figures `pt-render bench` measures, as rows of (section, figure, variant,
// value, unit), printed as a table and written as JSON. Timings are medians of several runs
// after a warm-up run that is not counted.
#include <cstdint>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "render/util/stopwatch.h"

namespace pt::cli {

struct BenchRow {
    std::string section;  // "rays", "path tracing", "BVH", "edit to first frame", "image check"
    std::string figure;   // e.g. "primary", "BLAS build (GPU LBVH)"
    std::string variant;  // toggles, e.g. "default", "megakernel", "BVH off"
    double value = 0.0;
    std::string unit;
    std::string note;  // e.g. why a variant was refused, or the sync action
};

class BenchReport {
public:
    void add(BenchRow row);
    void print(std::FILE* out) const;
    nlohmann::ordered_json json() const;
    const std::vector<BenchRow>& rows() const { return rows_; }

private:
    std::vector<BenchRow> rows_;
};

// Median of `values` (the mean of the middle two for an even count); 0 for none.
double median(std::vector<double> values);

// Runs `fn` once to warm up, then `runs` times; each timed run's seconds.
template <class Fn>
std::vector<double> timeRuns(uint32_t runs, Fn&& fn) {
    fn();
    std::vector<double> seconds;
    for (uint32_t r = 0; r < runs; ++r) {
        const auto start = Clock::now();
        fn();
        seconds.push_back(secondsSince(start));
    }
    return seconds;
}

}  // namespace pt::cli
