#include "render/bvh/background_bvh_build.h"

#include <chrono>

namespace pt {

BackgroundBvhBuild::BackgroundBvhBuild(std::vector<Aabb> primBounds) : primBounds_(std::move(primBounds)) {
    thread_ = std::thread([this] {
        const auto start = std::chrono::steady_clock::now();
        result_ = buildBinnedSahBvh(primBounds_.data(), uint32_t(primBounds_.size()));
        primBounds_ = {};  // its memory back as soon as the tree no longer needs it
        seconds_ = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        ready_.store(true, std::memory_order_release);
    });
}

BackgroundBvhBuild::~BackgroundBvhBuild() {
    if (thread_.joinable()) thread_.join();
}

Bvh BackgroundBvhBuild::take() {
    if (thread_.joinable()) thread_.join();
    return std::move(result_);
}

}  // namespace pt
