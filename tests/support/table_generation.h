#pragma once
// Helpers of the DISABLED_GenerateTable tests that write the renderer's precomputed tables
// (render/materials/*_table.h): a two-thread loop and the writing of the generated header.
#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>
#include <string>
#include <thread>

namespace pt::test {

// Runs f(k) for k in [0, n) on two threads.
template <typename F>
void parallelFor(int n, F f) {
    std::thread other([&] {
        for (int k = 1; k < n; k += 2) f(k);
    });
    for (int k = 0; k < n; k += 2) f(k);
    other.join();
}

// Writes `text` to the file $`pathVariable` names, or to stdout where it is unset.
inline void writeGeneratedTable(const std::string& text, const char* pathVariable) {
    const char* path = std::getenv(pathVariable);
    if (!path) {
        std::fputs(text.c_str(), stdout);
        return;
    }
    FILE* file = std::fopen(path, "w");
    ASSERT_NE(file, nullptr) << path;
    std::fputs(text.c_str(), file);
    std::fclose(file);
}

}  // namespace pt::test
