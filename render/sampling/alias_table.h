#pragma once
// Walker/Vose alias table: draws index i with probability weight[i] / sum in O(1).
#include <cstdint>

#include "render/math/hd.h"
#include "render/math/span.h"

namespace pt {

// Walker alias table entry: pick i uniformly, keep it with probability `keep`, else `alias`.
struct AliasEntry {
    float keep;
    uint32_t alias;
};

// The table is built on the host by alias_table_builder.h.

// Device and host: draws an index from `u` in [0, 1).
PT_HD uint32_t sampleAliasTable(Span<const AliasEntry> table, float u) {
    const float scaled = u * float(table.count);
    uint32_t i = uint32_t(scaled);
    if (i >= table.count) i = table.count - 1;
    const float remainder = scaled - float(i);
    return remainder < table[i].keep ? i : table[i].alias;
}

}  // namespace pt
