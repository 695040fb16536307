#include "render/bvh/background_bvh_build.h"

#include <tbb/task_arena.h>

namespace pt {

BackgroundBvhBuild::BackgroundBvhBuild(LargeArray<Aabb> primBounds) : primBounds_(std::move(primBounds)) {
    thread_ = std::thread([this] {
        try {
            tbb::task_arena arena;
            arena.execute(
                [&] { result_ = buildBinnedSahBvh(primBounds_.data(), uint32_t(primBounds_.size())); });
        } catch (...) {
            failure_ = std::current_exception();  // std::thread would terminate the program
        }
        primBounds_ = {};  // its memory back as soon as the tree no longer needs it
        ready_.store(true, std::memory_order_release);
    });
}

BackgroundBvhBuild::~BackgroundBvhBuild() {
    if (thread_.joinable()) thread_.join();
}

Bvh BackgroundBvhBuild::take() {
    if (thread_.joinable()) thread_.join();
    if (failure_) std::rethrow_exception(failure_);
    return std::move(result_);
}

}  // namespace pt
