#include "render/bvh/background_bvh_build.h"

#include <tbb/task_arena.h>

namespace pt {

BackgroundBvhBuild::BackgroundBvhBuild(LargeArray<Aabb> primBounds, bool compressed)
    : primBounds_(std::move(primBounds)), wantsCompressed_(compressed) {
    thread_ = std::thread([this] {
        try {
            tbb::task_arena arena;
            arena.execute(
                [&] { result_ = buildBinnedSahBvh(primBounds_.data(), uint32_t(primBounds_.size())); });
        } catch (...) {
            failure_ = std::current_exception();  // std::thread would terminate the program
        }
        primBounds_ = {};  // its memory back as soon as the tree no longer needs it
        {
            std::lock_guard<std::mutex> lock(treeMutex_);
            treeReady_.store(true, std::memory_order_release);
        }
        treeSignal_.notify_all();
        if (wantsCompressed_ && !failure_) {
            try {
                compressed_ = compressToWide(result_.nodes.data(), uint32_t(result_.nodes.size()),
                                             result_.primIndices.data());
            } catch (...) {
                compressed_ = {};  // out of memory, say: the tree stands without it
            }
        }
        finished_.store(true, std::memory_order_release);
    });
}

BackgroundBvhBuild::~BackgroundBvhBuild() {
    if (thread_.joinable()) thread_.join();
}

const Bvh& BackgroundBvhBuild::tree() {
    {
        std::unique_lock<std::mutex> lock(treeMutex_);  // not a join: the thread may go on compressing
        treeSignal_.wait(lock, [this] { return ready(); });
    }
    if (failure_) std::rethrow_exception(failure_);
    return result_;
}

CompressedWideBvh BackgroundBvhBuild::takeCompressed() {
    if (thread_.joinable()) thread_.join();
    return std::move(compressed_);
}

}  // namespace pt
