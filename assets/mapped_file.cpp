#include "assets/mapped_file.h"

#include <fcntl.h>
#include <sys/mman.h>
#include <sys/stat.h>
#include <unistd.h>

#include <utility>

#include "assets/input_error.h"

namespace pt {

MappedFile::MappedFile(const std::string& path, const std::string& label) {
    const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
    struct stat info {};
    if (fd < 0 || ::fstat(fd, &info) != 0 || !S_ISREG(info.st_mode)) {
        if (fd >= 0) ::close(fd);
        throw InputError(label + ": cannot open '" + path + "'");
    }
    if (uint64_t(info.st_size) > UINT32_MAX) {
        ::close(fd);
        throw InputError(label + ": file larger than 4 GiB");
    }
    size_ = size_t(info.st_size);
    if (size_ > 0) {
        // MAP_POPULATE: the page tables filled in one call, not one fault a 4 KiB page as the
        // import reads them.
        data_ = ::mmap(nullptr, size_, PROT_READ, MAP_PRIVATE | MAP_POPULATE, fd, 0);
        if (data_ == MAP_FAILED) {
            data_ = nullptr;
            size_ = 0;
            ::close(fd);
            throw InputError(label + ": cannot map '" + path + "'");
        }
    }
    ::close(fd);  // the mapping keeps the file
}

MappedFile::MappedFile(MappedFile&& other) noexcept
    : data_(std::exchange(other.data_, nullptr)), size_(std::exchange(other.size_, 0)) {}

MappedFile& MappedFile::operator=(MappedFile&& other) noexcept {
    if (this != &other) {
        unmap();
        data_ = std::exchange(other.data_, nullptr);
        size_ = std::exchange(other.size_, 0);
    }
    return *this;
}

MappedFile::~MappedFile() { unmap(); }

void MappedFile::unmap() {
    if (data_) ::munmap(data_, size_);
    data_ = nullptr;
    size_ = 0;
}

}  // namespace pt
