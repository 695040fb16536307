// Error messages stay one bounded line whatever the input holds (issue 17): values quoted
// shortened, control characters escaped, the right words for folders and empty files.
#include "assets/message_text.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <utility>

#include "assets/model_import.h"
#include "assets/scene_loader.h"
#include "support/input_error_of.h"
#include "support/test_paths.h"

namespace pt {
namespace {

TEST(MessageText, ShortenedCutsLongTextWithAnEllipsisAndNeverSplitsACharacter) {
    EXPECT_EQ(shortened("short"), "short");
    const std::string cut = shortened(std::string(500, 'a'));
    EXPECT_EQ(cut.size(), kMaxQuotedChars);
    EXPECT_EQ(cut.substr(cut.size() - 3), "...");
    std::string accents;
    for (int i = 0; i < 100; ++i) accents += "\xc3\xa9";  // U+00E9, two bytes each
    const std::string kept = shortened(accents, 10);      // 7 bytes would split the 4th
    EXPECT_EQ(kept, "\xc3\xa9\xc3\xa9\xc3\xa9...");
}

TEST(MessageText, ControlCharactersAreEscapedAndMessagesBounded) {
    EXPECT_EQ(escapedControls("a\x1b[31mred\n\tb\x7f"), "a\\x1b[31mred\\n\\tb\\x7f");
    const std::string huge(10'000'000, '\n');
    const std::string line = oneLineMessage("f.json: " + huge);
    EXPECT_LE(line.size(), kMaxMessageChars);
    EXPECT_EQ(line.find('\n'), std::string::npos);
    EXPECT_EQ(line.rfind("f.json: \\n\\n", 0), 0u);
}

TEST(MessageText, AHugeGltfValueIsQuotedShortened) {
    const std::string path = test::writeTempFile(
        "huge_type.gltf",
        "{\"asset\": {\"version\": \"2.0\"}, \"accessors\": [{\"count\": 1, \"componentType\": 5126, "
        "\"type\": \"" +
            std::string(10'000'000, 'V') + "\"}]}");
    Scene scene;
    const std::string message = test::inputErrorOf([&] { importGltf(path, 0, scene); });
    EXPECT_EQ(message.rfind("huge_type.gltf: accessors[0].type: \"VVV", 0), 0u) << message.substr(0, 200);
    EXPECT_NE(message.find("VVV... is not a glTF accessor type"), std::string::npos)
        << message.substr(0, 200);
    EXPECT_LT(message.size(), 200u);
}

TEST(MessageText, LoadSceneEscapesAndBoundsWhatTheFileHolds) {
    // JSON escapes in the file: the key itself holds ESC and a newline.
    const std::string key = "\\u001b[2J\\n" + std::string(5000, 'k');
    const std::string path =
        test::writeTempFile("escape.json", "{\"version\": 1, \"" + key + "\": 0, \"objects\": []}");
    const LoadResult r = loadScene(path);
    ASSERT_FALSE(r.ok());
    EXPECT_NE(r.error.find("unknown key \"\\u001b[2J\\n"), std::string::npos) << r.error.substr(0, 200);
    EXPECT_LE(r.error.size(), kMaxMessageChars);
    for (const char c : r.error) EXPECT_GE(static_cast<unsigned char>(c), 0x20u) << "a control character";
}

TEST(MessageText, FoldersAndEmptyFilesAreCalledWhatTheyAre) {
    const std::string folder = test::tempDir() + "/a_folder.json";
    std::filesystem::create_directories(folder);
    EXPECT_EQ(loadScene(folder).error, folder + ": a folder, not a file");
    const std::string empty = test::writeTempFile("empty.gltf", "");
    EXPECT_EQ(loadScene(empty).error, empty + ": empty file");
    const std::string missing = test::tempDir() + "/missing.json";
    EXPECT_EQ(loadScene(missing).error, missing + ": no such file");
}

// A glTF whose image is a folder or an empty file still loads, with a warning in the right
// words (a folder crashed tinygltf's own file reader with std::bad_alloc).
TEST(MessageText, GltfImagesThatAreFoldersOrEmptyWarnInTheRightWords) {
    const std::string fixture = test::readTextFile(test::testDataPath("gltf/missing_image.gltf"));
    const std::string missing = "does_not_exist.png";
    ASSERT_NE(fixture.find(missing), std::string::npos);
    std::filesystem::create_directories(test::tempDir() + "/folder.png");
    test::writeTempFile("empty.png", "");
    for (const auto& [image, words] :
         {std::pair<std::string, std::string>{"folder.png", "image a folder, not a file"},
          {"empty.png", "image empty file"},
          {"absent.png", "image no such file"}}) {
        std::string text = fixture;
        text.replace(text.find(missing), missing.size(), image);
        const std::string path = test::writeTempFile("uses_" + image + ".gltf", text);
        Scene scene;
        EXPECT_NO_THROW(importGltf(path, 0, scene)) << image;
        ASSERT_EQ(scene.warnings.size(), 1u) << image;
        EXPECT_NE(scene.warnings[0].find("'" + image + "': " + words), std::string::npos)
            << scene.warnings[0];
    }
}

}  // namespace
}  // namespace pt
