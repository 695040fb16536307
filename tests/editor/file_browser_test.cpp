// The in-app file browser's model (editor/file_browser.h): what a folder lists and in which
// order, moving in and up, and one clear line where a folder cannot be listed.
#include "editor/file_browser.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "support/test_paths.h"

namespace pt::editor {
namespace {

namespace fs = std::filesystem;

// tmp/browse: folders "Models" and "assets" and ".git", files of several kinds and cases.
std::string makeFolder() {
    const fs::path root = fs::path(test::tempDir()) / "browse";
    fs::remove_all(root);
    for (const char* folder : {"Models", "assets", ".git", "assets/inner"})
        fs::create_directories(root / folder);
    for (const char* file :
         {"b.json", "A.JSON", "c.gltf", "notes.txt", ".hidden.json", "assets/inner/x.glb"}) {
        std::ofstream(root / file) << "0123456789";
    }
    return root.string();
}

std::vector<std::string> names(const FileBrowser& browser) {
    std::vector<std::string> out;
    for (const FileEntry& e : browser.entries()) out.push_back(e.name + (e.folder ? "/" : ""));
    return out;
}

TEST(FileBrowser, FoldersFirstThenTheFilesAskedForByNameWithoutRegardToCase) {
    const std::string root = makeFolder();
    FileBrowser browser({".json", ".gltf"});
    ASSERT_TRUE(browser.open(root)) << browser.error();
    EXPECT_EQ(names(browser), (std::vector<std::string>{"assets/", "Models/", "A.JSON", "b.json", "c.gltf"}));
    EXPECT_EQ(browser.entries()[2].bytes, 10u);
    EXPECT_EQ(browser.folder(), fs::weakly_canonical(root).string());

    browser.setShowHidden(true);
    EXPECT_EQ(names(browser), (std::vector<std::string>{".git/", "assets/", "Models/", ".hidden.json",
                                                        "A.JSON", "b.json", "c.gltf"}));
    FileBrowser everything;
    ASSERT_TRUE(everything.open(root));
    EXPECT_EQ(names(everything).back(), "notes.txt") << "no extensions: every file";
}

TEST(FileBrowser, InAndUpAndTheCrumbsOfTheWay) {
    const std::string root = makeFolder();
    FileBrowser browser({".glb"});
    ASSERT_TRUE(browser.open(root));
    ASSERT_TRUE(browser.enter("assets"));
    ASSERT_TRUE(browser.enter("inner"));
    EXPECT_EQ(names(browser), std::vector<std::string>{"x.glb"});
    EXPECT_EQ(browser.pathOf("x.glb"), (fs::weakly_canonical(root) / "assets" / "inner" / "x.glb").string());
    const auto crumbs = browser.crumbs();
    ASSERT_GE(crumbs.size(), 3u);
    EXPECT_EQ(crumbs.back().first, "inner");
    EXPECT_EQ(crumbs.back().second, browser.folder());
    EXPECT_EQ(crumbs[crumbs.size() - 2].first, "assets");
    EXPECT_EQ(crumbs.front().second, "/");
    ASSERT_TRUE(browser.up());
    ASSERT_TRUE(browser.up());
    EXPECT_EQ(browser.folder(), fs::weakly_canonical(root).string());
    FileBrowser atRoot;
    ASSERT_TRUE(atRoot.open("/"));
    EXPECT_FALSE(atRoot.up()) << "nothing above the root";
}

TEST(FileBrowser, AFolderThatCannotBeListedKeepsTheListingAndSaysWhy) {
    const std::string root = makeFolder();
    FileBrowser browser({".json"});
    ASSERT_TRUE(browser.open(root));
    const std::vector<std::string> before = names(browser);
    EXPECT_FALSE(browser.enter("no such folder"));
    EXPECT_NE(browser.error().find("no such folder"), std::string::npos) << browser.error();
    EXPECT_EQ(browser.error().find('\n'), std::string::npos) << "one line";
    EXPECT_EQ(names(browser), before);
    EXPECT_EQ(browser.folder(), fs::weakly_canonical(root).string());
    EXPECT_FALSE(browser.enter("b.json")) << "a file is no folder";
    EXPECT_FALSE(browser.error().empty());
    EXPECT_TRUE(browser.refresh());
    EXPECT_TRUE(browser.error().empty()) << "a listing that works clears the error";
}

TEST(FileBrowser, DialogsStartInTheFoldersOfTheirPaths) {
    const std::string root = makeFolder();
    EXPECT_EQ(startFolder(root + "/b.json"), root);
    EXPECT_EQ(startFolder(root + "/not yet saved.json"), root) << "a new file's folder";
    EXPECT_EQ(startFolder(root + "/assets"), root + "/assets");
    EXPECT_EQ(startFolder("/no/such/place/scene.json"), fs::current_path().string());
    EXPECT_EQ(startFolder(""), fs::current_path().string());
    EXPECT_EQ(sizeText(999), "999 B");
    EXPECT_EQ(sizeText(12345678), "12.3 MB");
}

}  // namespace
}  // namespace pt::editor
