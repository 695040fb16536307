#pragma once
// Host: builds the Walker/Vose alias table that alias_table.h samples. Apart from it so per-ray
// code, which only samples, does not include std::vector.
#include <cstddef>
#include <vector>

#include "render/sampling/alias_table.h"

namespace pt {

// Zero or negative weights are never drawn; all-zero input gives an empty table.
std::vector<AliasEntry> buildAliasTable(const std::vector<float>& weights);

}  // namespace pt
