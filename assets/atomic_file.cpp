#include "assets/atomic_file.h"

#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>

#include "assets/input_error.h"

namespace pt {
namespace fs = std::filesystem;

namespace {

std::string uniqueTempPath(const std::string& path) {
    static std::atomic<unsigned> counter{0};
    const fs::path target(path);
    // Keep the extension last: image writers pick the format from it.
    const std::string name = "." + target.stem().string() + ".tmp" + std::to_string(::getpid()) + "-" +
                             std::to_string(counter++) + target.extension().string();
    return (target.parent_path() / name).string();
}

}  // namespace

void writeFileAtomically(const std::string& path,
                         const std::function<void(const std::string& tempPath)>& writeTemp) {
    const fs::path target(path);
    std::error_code ec;
    if (!target.parent_path().empty() && !fs::is_directory(target.parent_path(), ec)) {
        throw InputError(path + ": folder " + target.parent_path().string() + " does not exist");
    }
    const std::string temp = uniqueTempPath(path);
    try {
        writeTemp(temp);
    } catch (...) {
        fs::remove(temp, ec);
        throw;
    }
    if (std::rename(temp.c_str(), path.c_str()) != 0) {
        const std::string reason = std::strerror(errno);
        fs::remove(temp, ec);
        throw InputError(path + ": cannot replace file: " + reason);
    }
}

void writeTextAtomically(const std::string& path, const std::string& content) {
    writeFileAtomically(path, [&](const std::string& temp) {
        std::ofstream out(temp, std::ios::binary | std::ios::trunc);
        out.write(content.data(), std::streamsize(content.size()));
        out.close();
        if (!out) throw InputError(path + ": write failed");
    });
}

}  // namespace pt
