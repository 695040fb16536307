#pragma once
// A binned SAH build (binned_sah_builder.h) on a thread of its own, for a tree wanted soon but
// not before the first frame: the CUDA backend's first frame of a large mesh walks an LBVH
// built on the GPU in milliseconds while this builds the SAH tree behind it (issue 21; on the
// H200's host, 1.5 s of a 10M-triangle sphere's 2.3 s first sync was the host build).
// The build owns its input, so nothing it reads changes under it, and runs its tasks in a TBB
// arena of its own: a thread waiting in another parallel loop (the render thread's) steals only
// from its own arena, never a subtree of this build.
#include <atomic>
#include <exception>
#include <thread>
#include <vector>

#include "render/bvh/binned_sah_builder.h"
#include "render/util/large_array.h"

namespace pt {

class BackgroundBvhBuild {
public:
    // Starts building over `primBounds` (moved in: the thread's own copy).
    explicit BackgroundBvhBuild(LargeArray<Aabb> primBounds);
    // Waits for the thread: a build cannot be stopped half way.
    ~BackgroundBvhBuild();
    BackgroundBvhBuild(const BackgroundBvhBuild&) = delete;
    BackgroundBvhBuild& operator=(const BackgroundBvhBuild&) = delete;

    // Whether the tree is built; never blocks.
    bool ready() const { return ready_.load(std::memory_order_acquire); }
    // The tree, waiting for it if need be; once. Throws what the build threw (std::bad_alloc).
    Bvh take();

private:
    LargeArray<Aabb> primBounds_;
    Bvh result_;
    std::exception_ptr failure_;
    std::atomic<bool> ready_{false};
    std::thread thread_;
};

}  // namespace pt
