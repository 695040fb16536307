// Every test program's main (in place of gtest_main). After the tests it joins oneTBB's worker
// threads and, in the sanitized build, runs LeakSanitizer's check itself.
//
// Why: LeakSanitizer's exit-time check stops every thread with ptrace and scans their stacks
// from a tracer thread. At exit, static destructors have begun tearing down thread pools
// (oneTBB's workers, OpenImageIO's pool) whose threads may still be exiting, and the tracer
// can fault on a stack that goes away under it ("Tracer caught signal 11 ... LeakSanitizer has
// encountered a fatal error"): the CI run of 22085cf failed that way twice in a row, after all
// of pt_assets_tests' tests had passed. Here every pool is intact and parked, and oneTBB's
// workers are gone, so the check sees a still process. __lsan_do_leak_check is the exit-time
// check moved earlier: a leak still ends the program with LeakSanitizer's report and exit
// code, and the check does not run again at exit.
#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include <new>

#if defined(__has_feature)
#if __has_feature(address_sanitizer)
#define PT_TEST_LEAK_CHECK 1
#endif
#endif
#if defined(__SANITIZE_ADDRESS__)
#define PT_TEST_LEAK_CHECK 1
#endif

#if defined(PT_TEST_LEAK_CHECK)
#include <sanitizer/lsan_interface.h>
#endif

int main(int argc, char** argv) {
    // Taken before any test starts TBB's scheduler, so that finalize below owns the last
    // reference to it and may wait for the workers.
    tbb::task_scheduler_handle tbbWorkers{tbb::attach{}};
    testing::InitGoogleTest(&argc, argv);
    const int result = RUN_ALL_TESTS();
    // Returns false (and does nothing) where something still holds the scheduler.
    tbb::finalize(tbbWorkers, std::nothrow);
#if defined(PT_TEST_LEAK_CHECK)
    __lsan_do_leak_check();
#endif
    return result;
}
