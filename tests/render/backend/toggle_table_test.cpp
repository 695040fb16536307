// The toggle table (issue 16): every toggle has one row, its keys and flags are unique (the CLI
// and converge keys are read from it), and each row reads and writes its own field only.
#include "render/backend/toggle_table.h"

#include <gtest/gtest.h>

#include <set>
#include <string>

#include "render/backend/toggle_states.h"

namespace pt {
namespace {

TEST(ToggleTable, EveryToggleHasOneRowWithUniqueKeysAndFlags) {
    std::set<int> ids;
    std::set<std::string> keys, labels, flags;
    for (const ToggleRow& row : toggleTable()) {
        EXPECT_TRUE(ids.insert(int(row.id)).second) << row.key;
        EXPECT_TRUE(keys.insert(row.key).second) << row.key;
        EXPECT_TRUE(labels.insert(row.label).second) << row.label;
        for (const char* flag : {row.onFlag, row.offFlag}) {
            if (*flag) {
                EXPECT_TRUE(flags.insert(flag).second) << flag;
            }
        }
        EXPECT_EQ(&toggleRow(row.id), &row);
    }
    EXPECT_EQ(ids.size(), size_t(ToggleId::GpuLeafCollapse) + 1) << "an id without a row";
}

TEST(ToggleTable, EachRowFlipsItsOwnToggleOnly) {
    const IntegratorToggles defaults;
    const std::vector<ToggleState> before = integratorToggleStates(defaults);
    for (const ToggleRow& row : toggleTable()) {
        SCOPED_TRACE(row.key);
        IntegratorToggles t = defaults;
        row.set(t, !row.get(defaults));
        EXPECT_NE(row.get(t), row.get(defaults));
        const std::vector<ToggleState> after = integratorToggleStates(t);
        ASSERT_EQ(after.size(), before.size());
        for (size_t i = 0; i < after.size(); ++i) {
            EXPECT_EQ(after[i].name, before[i].name);
            EXPECT_EQ(after[i].requested != before[i].requested, after[i].id == row.id) << after[i].name;
        }
    }
    // "bvh" on means the BVH is used: brute force off.
    EXPECT_TRUE(toggleRow(ToggleId::Bvh).get(defaults));
    EXPECT_FALSE(defaults.bruteForce);
}

}  // namespace
}  // namespace pt
