#pragma once
// An uninitialised array of trivially copyable elements for a build's input and scratch memory,
// written in parallel by its owner (a std::vector first fills it on one thread), backed by
// transparent huge pages where the kernel offers them on request (Linux, THP mode "madvise").
// A build of 1M triangles touches about 100 MB of fresh memory; in 4 KiB pages each first touch
// is a fault and a page cleared (a tenth of the binned SAH build's samples under perf), in
// 2 MiB pages one fault in 512: one thread's build of a 1M-triangle sphere went from 299 to
// 278 ms with its scratch and its nodes on huge pages.
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <memory>
#include <new>
#include <type_traits>
#include <vector>

#if defined(__linux__)
#include <sys/mman.h>
#endif

namespace pt {

constexpr size_t kHugePageBytes = size_t(2) << 20;

// Asks for huge pages under the whole 2 MiB pages of [memory, memory + bytes) that nothing has
// touched yet (a std::vector's reserved storage); harmless where they are not offered.
inline void adviseHugePages(void* memory, size_t bytes) {
#if defined(__linux__) && defined(MADV_HUGEPAGE)
    const uintptr_t begin =
        (reinterpret_cast<uintptr_t>(memory) + kHugePageBytes - 1) / kHugePageBytes * kHugePageBytes;
    const uintptr_t end = (reinterpret_cast<uintptr_t>(memory) + bytes) / kHugePageBytes * kHugePageBytes;
    if (end > begin) madvise(reinterpret_cast<void*>(begin), end - begin, MADV_HUGEPAGE);
#else
    (void)memory;
    (void)bytes;
#endif
}

// Reserves room for `count` elements in `v` and asks for huge pages under it, before anything
// is written there: for the large arrays of a load and a compile (a 10M-triangle glTF reads
// 240 MB of file and writes several arrays as large), whose first touches in 4 KiB pages were
// 45% of the samples of its load and compile under perf. Fill with assign, insert or resize.
template <class T>
void reserveOnHugePages(std::vector<T>& v, size_t count) {
    v.reserve(count);
    adviseHugePages(v.data(), v.capacity() * sizeof(T));
}

template <class T>
class LargeArray {
    static_assert(std::is_trivially_copyable_v<T> && std::is_trivially_destructible_v<T>,
                  "LargeArray holds plain data it never constructs or destroys");

public:
    LargeArray() = default;
    explicit LargeArray(size_t count) : count_(count) {
        if (count == 0) return;
        // Below a huge page, a huge page would waste more than it saves.
        const bool huge = count * sizeof(T) >= kHugePageBytes;
        const size_t alignment = std::max(huge ? kHugePageBytes : alignof(std::max_align_t), alignof(T));
        const size_t bytes =
            (count * sizeof(T) + alignment - 1) / alignment * alignment;  // aligned_alloc's rule
        void* memory = std::aligned_alloc(alignment, bytes);
        if (!memory) throw std::bad_alloc();
        if (huge) adviseHugePages(memory, bytes);
        data_.reset(static_cast<T*>(memory));
    }

    LargeArray(LargeArray&& other) noexcept : data_(std::move(other.data_)), count_(other.count_) {
        other.count_ = 0;
    }
    LargeArray& operator=(LargeArray&& other) noexcept {
        data_ = std::move(other.data_);
        count_ = other.count_;
        other.count_ = 0;
        return *this;
    }

    T* data() const { return data_.get(); }
    bool empty() const { return count_ == 0; }
    size_t size() const { return count_; }
    T& operator[](size_t i) const { return data_.get()[i]; }

private:
    struct Free {
        void operator()(T* p) const { std::free(p); }
    };
    std::unique_ptr<T, Free> data_;
    size_t count_ = 0;
};

}  // namespace pt
