#pragma once
// DeviceBuffer<T>: one cudaMalloc'd array that grows but never shrinks (so edits that keep a
// scene's size reuse its memory), with checked uploads and downloads.
#include <cuda_runtime.h>

#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

#include "render/backend/cuda/cuda_check.h"
#include "render/math/span.h"
#include "render/util/check.h"

namespace pt::cuda {

// The capacity a builder's scratch grows to for `needed` items from `current`: at least half as
// much again, so that builds growing a little at a time do not reallocate each time.
inline uint32_t grownCapacity(uint32_t needed, uint32_t current) {
    return needed > current + current / 2 ? needed : current + current / 2;
}

template <class T>
class DeviceBuffer {
public:
    DeviceBuffer() = default;
    explicit DeviceBuffer(size_t count) { resize(count); }
    DeviceBuffer(const DeviceBuffer&) = delete;
    DeviceBuffer& operator=(const DeviceBuffer&) = delete;
    DeviceBuffer(DeviceBuffer&& other) noexcept { swap(other); }
    DeviceBuffer& operator=(DeviceBuffer&& other) noexcept {
        swap(other);
        return *this;
    }
    ~DeviceBuffer() {
        if (data_) cudaFree(data_);  // no throw from a destructor; a failure here is moot
    }

    // Sets the element count; contents are kept only when no reallocation happens.
    void resize(size_t count) {
        if (count > capacity_) {
            T* fresh = nullptr;
            PT_CUDA_CHECK(cudaMalloc(&fresh, count * sizeof(T)));
            if (data_) PT_CUDA_CHECK(cudaFree(data_));
            data_ = fresh;
            capacity_ = count;
        }
        size_ = count;
    }

    // Sets the element count to `count` (at least the current one), keeping the contents: a
    // reallocation, to exactly `count`, copies them on `stream`.
    void growKeeping(size_t count, cudaStream_t stream = nullptr) {
        PT_CHECK(count >= size_);
        if (count > capacity_) {
            DeviceBuffer grown(count);
            if (size_) {
                PT_CUDA_CHECK(
                    cudaMemcpyAsync(grown.data_, data_, size_ * sizeof(T), cudaMemcpyDeviceToDevice, stream));
            }
            swap(grown);  // the old memory goes with `grown`: cudaFree waits for the copy
        }
        size_ = count;
    }
    // Appends `count` elements after the current ones (growKeeping).
    void append(const T* host, size_t count, cudaStream_t stream = nullptr) {
        const size_t first = size_;
        growKeeping(first + count, stream);
        uploadAt(first, host, count, stream);
    }

    void upload(const T* host, size_t count, cudaStream_t stream = nullptr) {
        resize(count);
        if (count)
            PT_CUDA_CHECK(cudaMemcpyAsync(data_, host, count * sizeof(T), cudaMemcpyHostToDevice, stream));
    }
    void upload(const std::vector<T>& host, cudaStream_t stream = nullptr) {
        upload(host.data(), host.size(), stream);
    }
    // Writes `count` elements at element `offset` (within the current size).
    void uploadAt(size_t offset, const T* host, size_t count, cudaStream_t stream = nullptr) {
        PT_CHECK(offset + count <= size_);
        if (count) {
            PT_CUDA_CHECK(
                cudaMemcpyAsync(data_ + offset, host, count * sizeof(T), cudaMemcpyHostToDevice, stream));
        }
    }
    void download(std::vector<T>& host) const {
        host.resize(size_);
        if (size_) PT_CUDA_CHECK(cudaMemcpy(host.data(), data_, size_ * sizeof(T), cudaMemcpyDeviceToHost));
    }
    // Reads `count` elements from element `offset` (within the current size).
    void downloadAt(size_t offset, T* host, size_t count) const {
        PT_CHECK(offset + count <= size_);
        if (count) PT_CUDA_CHECK(cudaMemcpy(host, data_ + offset, count * sizeof(T), cudaMemcpyDeviceToHost));
    }
    std::vector<T> download() const {
        std::vector<T> host;
        download(host);
        return host;
    }
    void fillZero(cudaStream_t stream = nullptr) {
        if (size_) PT_CUDA_CHECK(cudaMemsetAsync(data_, 0, size_ * sizeof(T), stream));
    }

    T* data() const { return data_; }
    size_t size() const { return size_; }
    size_t bytes() const { return capacity_ * sizeof(T); }
    Span<const T> span() const { return {data_, uint32_t(size_)}; }

private:
    void swap(DeviceBuffer& other) noexcept {
        std::swap(data_, other.data_);
        std::swap(size_, other.size_);
        std::swap(capacity_, other.capacity_);
    }

    T* data_ = nullptr;
    size_t size_ = 0;
    size_t capacity_ = 0;
};

}  // namespace pt::cuda
