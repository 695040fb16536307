#pragma once
// The first passes of both GPU BVH builders (gpu_bvh.h: LBVH and PLOC): primitives sorted by
// the Morton code of their box centres (Karras, HPG 2012), so that primitives near each other in
// space are near each other in the order. Keeps its scratch memory between sorts.
#include <cuda_runtime.h>

#include <cstdint>

#include "render/backend/cuda/device_buffer.h"
#include "render/bvh/aabb.h"

namespace pt::cuda {

// A sorted key is the 30-bit Morton code (10 bits an axis, in the centres' common bounds) of a
// box centre << 32 | the box's index: unique even where centres coincide.
constexpr int kMortonBits = 30;
constexpr int kMortonIndexBits = 32;

class MortonSort {
public:
    // The `count` keys of `boxes` (which must hold no NaN), sorted, in device memory this object
    // owns until its next sort or release. Queued on `stream`; count >= 1.
    const uint64_t* sort(const Aabb* boxes, uint32_t count, cudaStream_t stream);
    void release();
    uint64_t bytes() const {
        return keys_.bytes() + sortedKeys_.bytes() + sortScratch_.bytes() + centroidBounds_.bytes() +
               reduceScratch_.bytes();
    }

private:
    // Grows the scratch to `count` keys and asks cub for its temporary storage sizes, which
    // happens only when the capacity grows: sorts of the same size or smaller reuse it.
    void reserve(uint32_t count);

    uint32_t capacity_ = 0;
    DeviceBuffer<uint64_t> keys_, sortedKeys_;
    DeviceBuffer<uint8_t> sortScratch_;
    DeviceBuffer<Aabb> centroidBounds_;  // one box: the bounds of all box centres
    DeviceBuffer<uint8_t> reduceScratch_;
};

}  // namespace pt::cuda
