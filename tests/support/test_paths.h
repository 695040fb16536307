#pragma once
// Where tests find data. The shared sample assets live outside the project; their folder is
// $PT_SHARED_ASSETS, else the path CMake was configured with. Tests that need them call
// sharedAssetOrSkip(), which skips the test with a message when the file is absent.
#include <string>

namespace pt::test {

std::string sharedAssetsDir();
bool sharedAssetExists(const std::string& relativePath);
std::string sharedAsset(const std::string& relativePath);
std::string projectPath(const std::string& relativePath);   // under the source tree
std::string testDataPath(const std::string& relativePath);  // under tests/data
std::string tempDir();                                      // fresh, per test process
// Writes `bytes` to tempDir()/name and returns the path.
std::string writeTempFile(const std::string& name, const std::string& bytes);
std::string readTextFile(const std::string& path);  // "" where it cannot be read

}  // namespace pt::test

// Skips the current test when a shared asset is missing.
#define PT_REQUIRE_SHARED_ASSET(rel)                                                                         \
    do {                                                                                                     \
        if (!::pt::test::sharedAssetExists(rel))                                                             \
            GTEST_SKIP() << "shared asset " << (rel) << " not found under " << ::pt::test::sharedAssetsDir() \
                         << " (set PT_SHARED_ASSETS)";                                                       \
    } while (0)

// Skips the current test in a build without OpenImageIO (configured with PT_OIIO=OFF), where
// EXR images can be neither read nor written.
#define PT_REQUIRE_OIIO()                                                                      \
    do {                                                                                       \
        if (!PT_TEST_HAVE_OIIO) GTEST_SKIP() << "this build has no OpenImageIO (PT_OIIO=OFF)"; \
    } while (0)
