#pragma once
// SlicedArray<T>: an array of plain structs stored as a structure of arrays of 16-byte slices.
// Slice k of element i lives at planes[k * stride + i], so a warp that loads or stores
// elements i .. i + 31 moves 512 contiguous bytes per slice with one 16-byte access a lane,
// where an array of structs (116-byte PathStates) costs a scalar access per member with lanes
// 116 bytes apart: measured with Nsight Compute on the wavefront's shade kernel (Cornell box,
// 1080p), 81% of the L1 throughput and a third of the stalls were load/store queue throttling.
// Members are read and written by byte offset, touching only the slices they span.
#include <cuda_runtime.h>

#include <cstddef>
#include <cstdint>
#include <cstring>

namespace pt::cuda {

template <class T>
struct SlicedArray {
    static constexpr uint32_t kSlices = uint32_t((sizeof(T) + 15) / 16);

    uint4* planes = nullptr;  // kSlices planes of `stride` slices each
    uint32_t stride = 0;      // elements a plane holds

    __device__ __forceinline__ T load(uint32_t i) const {
        uint4 slices[kSlices];
        for (uint32_t k = 0; k < kSlices; ++k) slices[k] = planes[size_t(k) * stride + i];
        T value;
        memcpy(&value, slices, sizeof(T));
        return value;
    }

    __device__ __forceinline__ void store(uint32_t i, const T& value) const {
        uint4 slices[kSlices] = {};
        memcpy(slices, &value, sizeof(T));
        for (uint32_t k = 0; k < kSlices; ++k) planes[size_t(k) * stride + i] = slices[k];
    }

    // The member of type M at byte `offset` of element i (offsetof(T, member)).
    template <class M, size_t kOffset>
    __device__ __forceinline__ M loadMember(uint32_t i) const {
        constexpr uint32_t kFirst = kOffset / 16, kLast = (kOffset + sizeof(M) - 1) / 16;
        uint4 slices[kLast - kFirst + 1];
        for (uint32_t k = kFirst; k <= kLast; ++k) slices[k - kFirst] = planes[size_t(k) * stride + i];
        M value;
        memcpy(&value, reinterpret_cast<const unsigned char*>(slices) + (kOffset - 16 * kFirst), sizeof(M));
        return value;
    }

    template <class M, size_t kOffset>
    __device__ __forceinline__ void storeMember(uint32_t i, const M& value) const {
        constexpr uint32_t kFirst = kOffset / 16, kLast = (kOffset + sizeof(M) - 1) / 16;
        uint4 slices[kLast - kFirst + 1];
        for (uint32_t k = kFirst; k <= kLast; ++k) slices[k - kFirst] = planes[size_t(k) * stride + i];
        memcpy(reinterpret_cast<unsigned char*>(slices) + (kOffset - 16 * kFirst), &value, sizeof(M));
        for (uint32_t k = kFirst; k <= kLast; ++k) planes[size_t(k) * stride + i] = slices[k - kFirst];
    }
};

// A member of an element by name: PT_LOAD_MEMBER(paths, i, PathState, ray).
#define PT_LOAD_MEMBER(array, i, Type, member) \
    (array).template loadMember<decltype(Type::member), offsetof(Type, member)>(i)
#define PT_STORE_MEMBER(array, i, Type, member, value) \
    (array).template storeMember<decltype(Type::member), offsetof(Type, member)>(i, value)

}  // namespace pt::cuda
