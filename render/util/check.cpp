#include "render/util/check.h"

#include <cstdio>
#include <cstdlib>

namespace pt {

void checkFailed(const char* condition, const char* file, int line) {
    std::fprintf(stderr, "%s:%d: internal check failed: %s\n", file, line, condition);
    std::fflush(stderr);
    std::abort();
}

}  // namespace pt
