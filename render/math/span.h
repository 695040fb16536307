#pragma once
// Span: a pointer and a count, the only container type per-ray code sees. The memory
// belongs to whoever built the span (the render-scene compiler, or a backend's buffers).
#include <cstdint>

#include "render/math/hd.h"

namespace pt {

template <class T>
struct Span {
    T* data = nullptr;
    uint32_t count = 0;

    PT_HD T& operator[](uint32_t i) const { return data[i]; }
    PT_HD uint32_t size() const { return count; }
    PT_HD bool empty() const { return count == 0; }
    PT_HD T* begin() const { return data; }
    PT_HD T* end() const { return data + count; }
};

}  // namespace pt
