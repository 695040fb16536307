#pragma once
// PT_CHECK: an invariant checked in every build type, Release included (issue 16). For cheap
// tests on host code whose failure means a bug in this program, not bad input (bad input gets
// an error line naming the file and element, never an abort). A failed check prints the
// condition, file and line to stderr and aborts, so a sanitizer or debugger shows the stack.
// Hot per-ray loops keep `assert` (compiled out in Release) where a check would cost time.

namespace pt {

[[noreturn]] void checkFailed(const char* condition, const char* file, int line);

}  // namespace pt

#define PT_CHECK(condition) \
    ((condition) ? static_cast<void>(0) : ::pt::checkFailed(#condition, __FILE__, __LINE__))
