// The flat scene form that per-ray code reads (render/kernel/) stays below everything host-side:
// no std container (kernels compile under nvcc without the host library), and no include of the
// editable scene or of the compilers that build the flat form from it (issue 16).
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <regex>
#include <set>
#include <string>
#include <vector>

namespace {

namespace fs = std::filesystem;

struct Include {
    std::string file;
    int line;
    std::string target;
};

std::vector<Include> includesUnder(const fs::path& folder) {
    std::vector<Include> out;
    const std::regex include(R"(^\s*#\s*include\s*[<"]([^>"]+)[>"])");
    for (const auto& entry : fs::directory_iterator(folder)) {
        std::ifstream in(entry.path());
        std::string text;
        for (int line = 1; std::getline(in, text); ++line) {
            std::smatch m;
            if (std::regex_search(text, m, include))
                out.push_back({entry.path().filename().string(), line, m[1].str()});
        }
    }
    return out;
}

const fs::path kKernelFolder = fs::path(PT_SOURCE_DIR) / "render" / "kernel";

TEST(KernelLayering, TheFolderHoldsTheSceneForm) {
    ASSERT_TRUE(fs::exists(kKernelFolder / "render_scene.h")) << kKernelFolder;
    ASSERT_TRUE(fs::exists(kKernelFolder / "scene_arrays.h")) << kKernelFolder;
    EXPECT_FALSE(includesUnder(kKernelFolder).empty());
}

TEST(KernelLayering, NoHeaderIncludesAStdContainer) {
    const std::set<std::string> containers = {
        "vector", "string", "map",    "unordered_map", "set",      "unordered_set", "deque",
        "list",   "array",  "memory", "functional",    "optional", "variant"};
    for (const Include& i : includesUnder(kKernelFolder))
        EXPECT_EQ(containers.count(i.target), 0u)
            << i.file << ":" << i.line << " includes <" << i.target << ">";
}

TEST(KernelLayering, NoHeaderIncludesTheHostSceneOrItsCompilers) {
    for (const Include& i : includesUnder(kKernelFolder)) {
        for (const char* host : {"render/scene/", "render/compile/", "render/backend/"})
            EXPECT_NE(i.target.rfind(host, 0), 0u) << i.file << ":" << i.line << " includes " << i.target;
    }
}

}  // namespace
