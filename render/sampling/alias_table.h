#pragma once
// Walker/Vose alias table: draws index i with probability weight[i] / sum in O(1).
#include <cstdint>
#include <vector>

#include "render/scene/render_scene.h"

namespace pt {

// Host: builds the table. Zero or negative weights are never drawn; all-zero input gives an
// empty table.
std::vector<AliasEntry> buildAliasTable(const std::vector<float>& weights);

// Device and host: draws an index from `u` in [0, 1).
PT_HD uint32_t sampleAliasTable(Span<const AliasEntry> table, float u) {
    const float scaled = u * float(table.count);
    uint32_t i = uint32_t(scaled);
    if (i >= table.count) i = table.count - 1;
    const float remainder = scaled - float(i);
    return remainder < table[i].keep ? i : table[i].alias;
}

}  // namespace pt
