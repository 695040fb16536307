#include "render/sampling/alias_table_builder.h"

namespace pt {

std::vector<AliasEntry> buildAliasTable(const std::vector<float>& weights) {
    double total = 0.0;
    for (float w : weights) total += w > 0.0f ? double(w) : 0.0;
    if (weights.empty() || total <= 0.0) return {};

    const size_t n = weights.size();
    std::vector<AliasEntry> table(n);
    std::vector<double> scaled(n);
    std::vector<uint32_t> small, large;
    for (size_t i = 0; i < n; ++i) {
        scaled[i] = (weights[i] > 0.0f ? double(weights[i]) : 0.0) * double(n) / total;
        (scaled[i] < 1.0 ? small : large).push_back(uint32_t(i));
    }
    while (!small.empty() && !large.empty()) {
        const uint32_t s = small.back(), l = large.back();
        small.pop_back();
        table[s] = {float(scaled[s]), l};
        scaled[l] -= 1.0 - scaled[s];
        if (scaled[l] < 1.0) {
            large.pop_back();
            small.push_back(l);
        }
    }
    // Leftovers are 1 up to rounding.
    for (uint32_t i : large) table[i] = {1.0f, i};
    for (uint32_t i : small) table[i] = {1.0f, i};
    return table;
}

}  // namespace pt
