// Atomic writes: readers see the old file or the new one, never a torn one, and a failed
// write leaves no trace (no temporary file, previous content intact).
#include "assets/atomic_file.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <stdexcept>

#include "assets/input_error.h"
#include "assets/scene_json/scene_json.h"
#include "scene_test_helpers.h"

namespace pt {
namespace {

namespace fs = std::filesystem;
using test::readFile;
using test::testFolder;
using test::writeFile;

size_t entriesIn(const std::string& folder) {
    return size_t(std::distance(fs::directory_iterator(folder), fs::directory_iterator()));
}

TEST(AtomicFile, MissingFolderFailsAndCreatesNothing) {
    const std::string folder = testFolder();
    const std::string path = folder + "/absent/out.json";
    try {
        writeTextAtomically(path, "{}");
        FAIL() << "wrote into a folder that does not exist";
    } catch (const InputError& e) {
        EXPECT_EQ(std::string(e.what()), path + ": folder " + folder + "/absent does not exist");
    }
    EXPECT_EQ(entriesIn(folder), 0u);
}

TEST(AtomicFile, FailingWriterKeepsThePreviousFileAndLeavesNoTemporary) {
    const std::string folder = testFolder();
    const std::string path = writeFile(folder, "scene.json", "previous");
    EXPECT_THROW(writeFileAtomically(path,
                                     [](const std::string& temp) {
                                         std::ofstream(temp) << "half a fi";
                                         throw std::runtime_error("disk full");
                                     }),
                 std::runtime_error);
    EXPECT_EQ(readFile(path), "previous");
    EXPECT_EQ(entriesIn(folder), 1u) << "the temporary file was removed";
}

TEST(AtomicFile, SuccessfulWriteReplacesTheContent) {
    const std::string folder = testFolder();
    const std::string path = writeFile(folder, "scene.json", "previous content, longer than the new one");
    writeTextAtomically(path, "new");
    EXPECT_EQ(readFile(path), "new");
    EXPECT_EQ(entriesIn(folder), 1u);
}

TEST(AtomicFile, SceneJsonIntoMissingFolderFails) {
    const std::string folder = testFolder();
    EXPECT_THROW(writeSceneJson(Scene{}, folder + "/absent/scene.json"), InputError);
    EXPECT_EQ(entriesIn(folder), 0u);
    writeSceneJson(Scene{}, folder + "/scene.json");
    EXPECT_EQ(readFile(folder + "/scene.json"), sceneToJson(Scene{}, folder + "/scene.json"));
}

}  // namespace
}  // namespace pt
