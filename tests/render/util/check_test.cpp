// PT_CHECK stays on in Release (this test runs in CI's Release build): a broken invariant
// aborts with the condition, file and line, and a holding one costs nothing visible.
#include "render/util/check.h"

#include <gtest/gtest.h>

namespace pt {
namespace {

int checkedDivide(int a, int b) {
    PT_CHECK(b != 0);
    return a / b;
}

TEST(CheckDeathTest, ABrokenInvariantAbortsNamingItInEveryBuild) {
    EXPECT_EQ(checkedDivide(6, 3), 2);
    EXPECT_DEATH(checkedDivide(1, 0), "check_test.cpp:[0-9]+: internal check failed: b != 0");
}

}  // namespace
}  // namespace pt
