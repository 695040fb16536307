// PFM, the lossless float format of builds without OpenImageIO: exact round trip, rows in the
// right order, big-endian and grey files, and clear errors for broken ones.
#include "assets/image/pfm_file.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "assets/input_error.h"
#include "support/input_error_of.h"

namespace pt {
namespace {

std::filesystem::path tempDir() {
    const auto dir = std::filesystem::temp_directory_path() / "pt_pfm_file_test";
    std::filesystem::create_directories(dir);
    return dir;
}

TEST(PfmFile, RoundTripsFloatsExactlyWithTheTopRowFirst) {
    const uint32_t w = 3, h = 2;
    std::vector<float> rgba(w * h * 4);
    for (size_t i = 0; i < rgba.size(); ++i)
        rgba[i] = i % 4 == 3 ? 1.0f : 1e-7f * float(i * i) + 0.1f * float(i);
    rgba[0] = 65504.0f * 3.0f;  // beyond half
    const std::string path = (tempDir() / "round.pfm").string();
    writePfm(path, w, h, rgba);
    uint32_t rw = 0, rh = 0;
    EXPECT_EQ(readPfm(path, rw, rh), rgba);
    EXPECT_EQ(rw, w);
    EXPECT_EQ(rh, h);
    EXPECT_TRUE(isPfmPath("a/B.PFM"));
    EXPECT_FALSE(isPfmPath("a/b.exr"));
}

TEST(PfmFile, ReadsBigEndianGreyFiles) {
    const std::string path = (tempDir() / "grey.pfm").string();
    {
        std::ofstream out(path, std::ios::binary);
        out << "Pf\n2 1\n1.0\n";
        const unsigned char bigEndian[] = {0x3f, 0x80, 0, 0, 0x40, 0, 0, 0};  // 1.0, 2.0
        out.write(reinterpret_cast<const char*>(bigEndian), sizeof bigEndian);
    }
    uint32_t w = 0, h = 0;
    const std::vector<float> rgba = readPfm(path, w, h);
    ASSERT_EQ(rgba.size(), 8u);
    EXPECT_EQ(rgba[0], 1.0f);
    EXPECT_EQ(rgba[2], 1.0f);
    EXPECT_EQ(rgba[4], 2.0f);
    EXPECT_EQ(rgba[7], 1.0f);
}

TEST(PfmFile, BrokenFilesNameThemselvesAndTheProblem) {
    const std::string truncated = (tempDir() / "truncated.pfm").string();
    std::ofstream(truncated, std::ios::binary) << "PF\n4 4\n-1.0\n" << std::string(20, 'x');
    const std::string notPfm = (tempDir() / "text.pfm").string();
    std::ofstream(notPfm) << "hello";
    uint32_t w, h;
    for (const auto& [path, problem] : {std::pair<std::string, std::string>{truncated, "truncated"},
                                        {notPfm, "not a PFM"},
                                        {(tempDir() / "missing.pfm").string(), "cannot open"}}) {
        try {
            readPfm(path, w, h);
            ADD_FAILURE() << path << " should not read";
        } catch (const InputError& e) {
            EXPECT_NE(std::string(e.what()).find(path), std::string::npos) << e.what();
            EXPECT_NE(std::string(e.what()).find(problem), std::string::npos) << e.what();
        }
    }
}

// Found by fuzzing (tests/fuzz, issue 17): a header of a few bytes claiming 33273 x 33332 made
// readPfm take 13 GB before it found the pixels missing.
TEST(PfmFile, SizeInTheHeaderIsCheckedAgainstTheFileBeforeAllocating) {
    const std::string path = (tempDir() / "claims_huge.pfm").string();
    std::ofstream(path, std::ios::binary) << "PF\n65536 65536\n-1.0\n" << std::string(12, 'x');
    uint32_t w, h;
    EXPECT_EQ(test::inputErrorOf([&] { readPfm(path, w, h); }),
              path + ": PFM pixel data is truncated (12 of 51539607552 bytes)");
}

}  // namespace
}  // namespace pt
