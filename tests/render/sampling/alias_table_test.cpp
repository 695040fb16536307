#include <gtest/gtest.h>

#include <cmath>

#include "render/sampling/alias_table_builder.h"

namespace pt {
namespace {

TEST(AliasTable, DrawsEachIndexInProportionToItsWeight) {
    const std::vector<float> weights = {1.0f, 0.0f, 3.0f, 0.5f, 5.5f, 0.0f, 2.0f};
    const std::vector<AliasEntry> table = buildAliasTable(weights);
    ASSERT_EQ(table.size(), weights.size());
    const Span<const AliasEntry> span{table.data(), uint32_t(table.size())};
    constexpr int kDraws = 1000000;
    std::vector<int> counts(weights.size(), 0);
    for (int i = 0; i < kDraws; ++i) ++counts[sampleAliasTable(span, (float(i) + 0.5f) / kDraws)];
    double total = 0;
    for (float w : weights) total += w;
    double chi2 = 0;
    for (size_t i = 0; i < weights.size(); ++i) {
        const double expected = kDraws * weights[i] / total;
        if (weights[i] == 0.0f) {
            EXPECT_EQ(counts[i], 0) << "zero-weight index " << i << " was drawn";
            continue;
        }
        chi2 += (counts[i] - expected) * (counts[i] - expected) / expected;
    }
    EXPECT_LT(chi2, 20.5);  // 5 degrees of freedom, p = 0.001
}

TEST(AliasTable, AllZeroWeightsGiveAnEmptyTable) {
    EXPECT_TRUE(buildAliasTable({0.0f, 0.0f}).empty());
    EXPECT_TRUE(buildAliasTable({}).empty());
}

}  // namespace
}  // namespace pt
