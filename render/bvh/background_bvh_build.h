#pragma once
// A binned SAH build (binned_sah_builder.h) on a thread of its own, for a tree wanted soon but
// not before the first frame: the CUDA backend's first frame of a large mesh walks an LBVH
// built on the GPU in milliseconds while this builds the SAH tree behind it (issue 21; on the
// H200's host, 1.5 s of a 10M-triangle sphere's 2.3 s first sync was the host build).
// With its compressed form asked for, the same thread then collapses the tree into the CUDA
// traversal's compressed 8-wide nodes (compressed_wide_bvh.h), so that a large mesh walks those
// in the end, as the meshes built before the first frame do. The tree is ready first, so that
// the wait for the collapse (125 ms for a 1M-triangle sphere) does not keep a SAH tree from
// landing.
// The build owns its input, so nothing it reads changes under it, and runs its tasks in a TBB
// arena of its own: a thread waiting in another parallel loop (the render thread's) steals only
// from its own arena, never a subtree of this build.
#include <atomic>
#include <condition_variable>
#include <exception>
#include <mutex>
#include <thread>
#include <vector>

#include "render/bvh/binned_sah_builder.h"
#include "render/bvh/compressed_wide_bvh.h"
#include "render/util/large_array.h"

namespace pt {

class BackgroundBvhBuild {
public:
    // Starts building over `primBounds` (moved in: the thread's own copy), and then its
    // compressed form where `compressed`.
    explicit BackgroundBvhBuild(LargeArray<Aabb> primBounds, bool compressed = false);
    // Waits for the thread: a build cannot be stopped half way.
    ~BackgroundBvhBuild();
    BackgroundBvhBuild(const BackgroundBvhBuild&) = delete;
    BackgroundBvhBuild& operator=(const BackgroundBvhBuild&) = delete;

    // Whether the tree is built; never blocks.
    bool ready() const { return treeReady_.load(std::memory_order_acquire); }
    // Whether the thread is done: the tree, and its compressed form where asked for.
    bool finished() const { return finished_.load(std::memory_order_acquire); }
    // The tree, waiting for it if need be; valid while this build lives. Throws what the build
    // threw (std::bad_alloc).
    const Bvh& tree();
    // The tree's compressed form, once, waiting for the thread; empty (no nodes) where not asked
    // for or where its collapse failed (the host ran out of memory: the tree stands without it).
    CompressedWideBvh takeCompressed();

private:
    LargeArray<Aabb> primBounds_;
    bool wantsCompressed_;
    Bvh result_;
    CompressedWideBvh compressed_;
    std::exception_ptr failure_;
    std::atomic<bool> treeReady_{false}, finished_{false};
    std::mutex treeMutex_;  // with treeSignal_: tree() sleeps until the tree is ready
    std::condition_variable treeSignal_;
    std::thread thread_;
};

}  // namespace pt
