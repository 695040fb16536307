#include "pt_render/bench/bench_report.h"

#include <algorithm>
#include <cstdio>

namespace pt::cli {

void BenchReport::add(BenchRow row) { rows_.push_back(std::move(row)); }

void BenchReport::print(std::FILE* out) const {
    std::string section;
    for (const BenchRow& r : rows_) {
        if (r.section != section) {
            section = r.section;
            std::fprintf(out, "\n%s\n", section.c_str());
        }
        std::fprintf(out, "  %-34s %-28s %12.4g %-10s %s\n", r.figure.c_str(), r.variant.c_str(), r.value,
                     r.unit.c_str(), r.note.c_str());
    }
}

nlohmann::ordered_json BenchReport::json() const {
    nlohmann::ordered_json rows = nlohmann::ordered_json::array();
    for (const BenchRow& r : rows_) {
        nlohmann::ordered_json j;
        j["section"] = r.section;
        j["figure"] = r.figure;
        j["variant"] = r.variant;
        j["value"] = r.value;
        j["unit"] = r.unit;
        if (!r.note.empty()) j["note"] = r.note;
        rows.push_back(j);
    }
    return rows;
}

double median(std::vector<double> values) {
    if (values.empty()) return 0.0;
    std::sort(values.begin(), values.end());
    const size_t n = values.size();
    return n % 2 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]);
}

}  // namespace pt::cli
