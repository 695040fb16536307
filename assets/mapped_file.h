#pragma once
// A file's bytes mapped read-only into memory (POSIX mmap) for as long as the object lives. A
// glTF's 240 MB .bin read into an array cost a fresh array, zeroed by the kernel and by the
// array, then a copy out of the page cache; mapped, its pages are the page cache's own.
#include <cstddef>
#include <cstdint>
#include <string>

#include "render/math/span.h"

namespace pt {

class MappedFile {
public:
    MappedFile() = default;
    // Throws InputError "<label>: cannot open '<path>'" where it is no regular file that opens,
    // "<label>: file larger than 4 GiB" (what a Span counts, and what tinygltf takes) and
    // "<label>: cannot map '<path>'".
    MappedFile(const std::string& path, const std::string& label);
    MappedFile(MappedFile&& other) noexcept;
    MappedFile& operator=(MappedFile&& other) noexcept;
    MappedFile(const MappedFile&) = delete;
    MappedFile& operator=(const MappedFile&) = delete;
    ~MappedFile();

    const uint8_t* data() const { return static_cast<const uint8_t*>(data_); }
    size_t size() const { return size_; }
    Span<const uint8_t> bytes() const { return {data(), uint32_t(size_)}; }

private:
    void unmap();

    void* data_ = nullptr;  // nullptr for an empty file (mmap maps no zero bytes)
    size_t size_ = 0;
};

}  // namespace pt
