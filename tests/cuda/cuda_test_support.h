#pragma once
// GPU tests build wherever nvcc exists and run where a CUDA device exists; elsewhere each one
// skips with the reason.
#include <gtest/gtest.h>

#include <string>

#include "render/backend/cuda/cuda_device.h"

#define PT_REQUIRE_CUDA_DEVICE()                                                     \
    do {                                                                             \
        std::string ptWhy_;                                                          \
        if (!::pt::cuda::deviceAvailable(&ptWhy_)) GTEST_SKIP() << "skipped: " << ptWhy_; \
    } while (0)
