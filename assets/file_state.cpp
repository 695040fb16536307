#include "assets/file_state.h"

#include <filesystem>

namespace pt {

FileState fileState(const std::string& path) {
    namespace fs = std::filesystem;
    std::error_code error;
    const fs::file_status status = fs::status(path, error);
    if (error || !fs::exists(status)) return FileState::Missing;
    if (fs::is_directory(status)) return FileState::Folder;
    if (!fs::is_regular_file(status)) return FileState::NotAFile;
    const auto size = fs::file_size(path, error);
    return !error && size == 0 ? FileState::Empty : FileState::Readable;
}

const char* fileStateWords(FileState state) {
    switch (state) {
        case FileState::Empty: return "empty file";
        case FileState::Missing: return "no such file";
        case FileState::Folder: return "a folder, not a file";
        case FileState::NotAFile: return "not a regular file";
        case FileState::Readable: break;
    }
    return "readable";
}

}  // namespace pt
