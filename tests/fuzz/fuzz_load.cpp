#include "fuzz_load.h"

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <stdexcept>

#include "assets/input_error.h"
#include "assets/scene_loader.h"
#include "render/compile/compile_scene.h"
#include "support/test_paths.h"

namespace pt::fuzz {

std::optional<Scene> loadAndCompile(const std::vector<std::string>& names, const uint8_t* data, size_t size) {
    const std::string bytes(reinterpret_cast<const char*>(data), size);
    std::vector<std::string> paths;
    for (const std::string& name : names) paths.push_back(test::writeTempFile(name, bytes));
    LoadResult loaded = loadScene(paths.front());
    for (const std::string& path : paths) std::filesystem::remove(path);
    if (!loaded.ok()) return std::nullopt;
    try {
        compileRenderScene(*loaded.scene);
    } catch (const std::invalid_argument&) {
        // The documented refusal (brute force over budget, a dangling index): not a crash.
    }
    return std::move(loaded.scene);
}

void readWrittenInput(const std::string& name, const uint8_t* data, size_t size,
                      const std::function<void(const std::string& path)>& read) {
    const std::string path =
        test::writeTempFile(name, std::string(reinterpret_cast<const char*>(data), size));
    try {
        read(path);
    } catch (const InputError&) {
    }
    std::filesystem::remove(path);
}

void fail(const std::string& what, const std::string& message) {
    std::fprintf(stderr, "fuzz finding: %s\n%s\n", what.c_str(), message.c_str());
    std::abort();
}

}  // namespace pt::fuzz
