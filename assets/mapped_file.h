#pragma once
// A file's bytes mapped read-only into memory (POSIX mmap) for as long as the object lives. A
// glTF's 240 MB .bin read into an array cost a fresh array, zeroed by the kernel and by the
// array, then a copy out of the page cache; mapped, its pages are the page cache's own.
#include <cstddef>
#include <cstdint>
#include <string>

namespace pt {

// Bytes someone else owns.
struct ByteSpan {
    const uint8_t* data = nullptr;
    size_t size = 0;
};

class MappedFile {
public:
    MappedFile() = default;
    // Throws InputError "<label>: cannot map '<path>'" where the file cannot be opened or mapped.
    MappedFile(const std::string& path, const std::string& label);
    MappedFile(MappedFile&& other) noexcept;
    MappedFile& operator=(MappedFile&& other) noexcept;
    MappedFile(const MappedFile&) = delete;
    MappedFile& operator=(const MappedFile&) = delete;
    ~MappedFile();

    const uint8_t* data() const { return static_cast<const uint8_t*>(data_); }
    size_t size() const { return size_; }
    ByteSpan bytes() const { return {data(), size_}; }

private:
    void unmap();

    void* data_ = nullptr;  // nullptr for an empty file (mmap maps no zero bytes)
    size_t size_ = 0;
};

}  // namespace pt
