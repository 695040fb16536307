#include "support/test_paths.h"

#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>

namespace pt::test {

std::string sharedAssetsDir() {
    const char* env = std::getenv("PT_SHARED_ASSETS");
    return env && *env ? env : PT_DEFAULT_SHARED_ASSETS;
}

bool sharedAssetExists(const std::string& relativePath) {
    return std::filesystem::exists(sharedAsset(relativePath));
}

std::string sharedAsset(const std::string& relativePath) { return sharedAssetsDir() + "/" + relativePath; }

// $PT_SOURCE_DIR overrides the configured source tree: test binaries built on one machine
// and run on another (the GPU machine) find the project's files where it was copied.
std::string projectPath(const std::string& relativePath) {
    const char* env = std::getenv("PT_SOURCE_DIR");
    return (env && *env ? std::string(env) : std::string(PT_SOURCE_DIR)) + "/" + relativePath;
}

std::string testDataPath(const std::string& relativePath) {
    const char* env = std::getenv("PT_SOURCE_DIR");
    if (env && *env) return std::string(env) + "/tests/data/" + relativePath;
    return std::string(PT_TEST_DATA_DIR) + "/" + relativePath;
}

std::string tempDir() {
    static const std::string dir = [] {
        auto base = std::filesystem::temp_directory_path() / ("pt-tests-" + std::to_string(::getpid()));
        std::filesystem::create_directories(base);
        return base.string();
    }();
    return dir;
}

std::string writeTempFile(const std::string& name, const std::string& bytes) {
    const std::string path = tempDir() + "/" + name;
    std::ofstream(path, std::ios::binary) << bytes;
    return path;
}

std::string readTextFile(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

}  // namespace pt::test
