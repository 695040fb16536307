// End-to-end tests of the pt-render command line: real process, real files.
#include <fcntl.h>
#include <gtest/gtest.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>
#include <thread>
#include <vector>

#include "app/cli_runner.h"
#include "assets/image/image_write.h"
#include "assets/scene_loader.h"
#include "support/test_paths.h"

extern char** environ;

namespace pt {
namespace {

namespace fs = std::filesystem;
using test::runCli;

std::string cornell() { return "'" + test::projectPath("scenes/cornell.json") + "'"; }

// What scenes/cornell.json uses (render/compile/scene_features.h), in bit order: its glass sphere
// (smooth, analytic), diffuse walls (specular 0), mirror box, lamp and eight instances.
const std::vector<std::string> kCornellFeatures = {"smooth_transmission", "specular_layer",     "metal",
                                                   "emissive_triangles",  "multiple_instances", "spheres"};

TEST(PtRenderCli, RendersExrPngAndStatsAndPrintsThePaths) {
    PT_REQUIRE_OIIO();  // renders to EXR
    const std::string dir = test::tempDir();
    const std::string exr = dir + "/c.exr", png = dir + "/c.png", stats = dir + "/c.json";
    const auto r = runCli("render " + cornell() + " -o " + exr + " --png " + png +
                          " --spp 4 --size 48x32 --stats " + stats + " --quiet");
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_EQ(r.out, exr + "\n" + png + "\n");
    uint32_t w = 0, h = 0;
    const std::vector<float> rgba = readImageRgba(exr, w, h);
    EXPECT_EQ(w, 48u);
    EXPECT_EQ(h, 32u);
    double sum = 0;
    for (float v : rgba) sum += v;
    EXPECT_GT(sum, 48 * 32);  // lit, not black (alpha alone would give exactly 48 * 32)
    EXPECT_TRUE(fs::exists(png));
    std::ifstream in(stats);
    const nlohmann::json j = nlohmann::json::parse(in);
    for (const char* key : {"spp", "seconds", "width", "height", "backend", "triangles", "instances", "rays",
                            "mrays_per_s", "nonfinite_samples"}) {
        EXPECT_TRUE(j.contains(key)) << key;
    }
    EXPECT_EQ(j["spp"], 4);
    EXPECT_EQ(j["width"], 48);
    EXPECT_EQ(j["backend"], "cpu");
    EXPECT_EQ(j["nonfinite_samples"], 0);
    EXPECT_GT(j["rays"].get<uint64_t>(), 48u * 32u * 4u);
    EXPECT_EQ(j["features"].get<std::vector<std::string>>(), kCornellFeatures);
    EXPECT_EQ(j["kernel_variant"], "");  // the CPU runs one generic kernel
    EXPECT_TRUE(j["kernel_features"].is_array());
    EXPECT_TRUE(j["kernel_features"].empty());
    EXPECT_FALSE(j.contains("schedule"));  // GPU schedules only
}

// AOVs asked for are a feature the backend adds to the scene's.
TEST(PtRenderCli, StatsFeaturesIncludeTheAovsAskedFor) {
    PT_REQUIRE_OIIO();  // AOVs are EXR layers
    const std::string dir = test::tempDir();
    const std::string stats = dir + "/aov.json";
    const auto r = runCli("render " + cornell() + " -o " + dir +
                          "/aov.exr --aov albedo --spp 1 --size 8x8 --stats " + stats + " --quiet");
    ASSERT_EQ(r.exitCode, 0) << r.err;
    std::ifstream in(stats);
    const nlohmann::json j = nlohmann::json::parse(in);
    std::vector<std::string> expected = kCornellFeatures;
    expected.push_back("aovs");
    EXPECT_EQ(j["features"].get<std::vector<std::string>>(), expected);
}

TEST(PtRenderCli, ErrorsExitNonZeroWithOneClearLine) {
    const std::string out = " -o " + test::tempDir() + "/x.exr";
    struct Case {
        std::string args;
        int code;
        std::string needle;
    };
    const Case cases[] = {
        {"render /nonexistent/scene.json" + out, 1, "/nonexistent/scene.json"},
        {"render " + cornell() + out + " --backend cuda", 1, "cuda"},
        {"render " + cornell() + out + " --backend vulkan", 1, "unknown backend"},
        {"render " + cornell() + out + " --spp 0", 2, "--spp"},
        {"render " + cornell() + out + " --size 12", 2, "WIDTHxHEIGHT"},
        {"render " + cornell() + out + " --spp 2 --time 1", 2, "exclude"},
        {"render " + cornell() + out + " --clamp -3", 2, "--clamp"},
        {"render " + cornell() + out + " --guide-samples 64", 2, "--denoise"},
        {"render " + cornell() + out + " --denoise --guide-samples 0", 2, "--guide-samples"},
        {"render " + cornell() + out + " --denoise --guide-samples many", 2, "--guide-samples"},
        {"render " + cornell(), 2, "output"},
        {"render " + cornell() + out + " --frobnicate", 2, "--frobnicate"},
        {"render " + cornell() + " -o /nonexistent-dir/x.exr --spp 1 --size 8x8 --quiet", 1,
         "/nonexistent-dir"},
        {"transmogrify", 2, "unknown command"},
    };
    for (const Case& c : cases) {
        const auto r = runCli(c.args);
        EXPECT_EQ(r.exitCode, c.code) << c.args << "\n" << r.err;
        EXPECT_NE(r.err.find(c.needle), std::string::npos) << c.args << "\nstderr: " << r.err;
        EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << c.args << "\nstderr: " << r.err;
    }
}

// --clamp limits indirect light only: a clamped Cornell box is darker, and still lit.
TEST(PtRenderCli, ClampDarkensIndirectLight) {
    PT_REQUIRE_OIIO();  // renders to EXR
    const std::string dir = test::tempDir();
    double sums[2] = {0, 0};
    const char* extra[2] = {"", " --clamp 0.01"};
    for (int i = 0; i < 2; ++i) {
        const std::string exr = dir + "/clamp" + std::to_string(i) + ".exr";
        const auto r =
            runCli("render " + cornell() + " -o " + exr + " --spp 8 --size 32x32 --quiet" + extra[i]);
        ASSERT_EQ(r.exitCode, 0) << r.err;
        uint32_t w = 0, h = 0;
        for (float v : readImageRgba(exr, w, h)) sums[i] += v;
    }
    EXPECT_LT(sums[1], 0.97 * sums[0]);
    EXPECT_GT(sums[1], 32 * 32 * 1.05);  // alpha alone would give exactly 32 * 32
}

TEST(PtRenderCli, BvhOffIsRefusedAboveItsBudget) {
    // The instanced scene traces 64 x 12,288 triangles, far over the brute-force budget.
    const auto r = runCli("render '" + test::projectPath("scenes/instances.json") + "' -o " +
                          test::tempDir() + "/i.exr --spp 1 --size 8x8 --bvh-off --quiet");
    EXPECT_EQ(r.exitCode, 1);
    EXPECT_NE(r.err.find("brute force"), std::string::npos) << r.err;
}

TEST(PtRenderCli, InfoReportsCountsAsJson) {
    const auto r = runCli("info " + cornell() + " --json");
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const nlohmann::json j = nlohmann::json::parse(r.out);
    EXPECT_EQ(j["triangles"], 6 * 2 + 12);  // six quads and one box
    EXPECT_EQ(j["spheres"], 1);
    EXPECT_EQ(j["instances"], 8);
    EXPECT_EQ(j["materials"], 6);
    EXPECT_EQ(j["emissive_triangles"], 2);
    EXPECT_EQ(j["sphere_lights"], 0);
    EXPECT_EQ(j["punctual_lights"], 0);
    EXPECT_EQ(j["features"].get<std::vector<std::string>>(), kCornellFeatures);
    for (const char* key :
         {"meshes", "textures", "bounds", "load_seconds", "blas_build_seconds", "tlas_build_seconds"}) {
        EXPECT_TRUE(j.contains(key)) << key;
    }
}

TEST(PtRenderCli, InfoPrintsTheFeaturesOnOneLine) {
    const auto r = runCli("info " + cornell() + " --quiet");
    ASSERT_EQ(r.exitCode, 0) << r.err;
    std::string expected = "\nfeatures ";
    expected.append(20 - 8, ' ');  // the key column is 20 wide
    for (size_t i = 0; i < kCornellFeatures.size(); ++i) expected += (i ? ", " : "") + kCornellFeatures[i];
    EXPECT_NE(r.out.find(expected + "\n"), std::string::npos) << r.out;

    // A scene using nothing says so (a smooth material: the default roughness would be glossy).
    const std::string empty = test::tempDir() + "/empty.json";
    std::ofstream(empty) << R"({"version": 1, "materials": [{"name": "m", "roughness": 0}],
        "objects": [{"name": "q", "shape": "quad", "material": "m"}]})";
    const auto bare = runCli("info '" + empty + "' --quiet");
    ASSERT_EQ(bare.exitCode, 0) << bare.err;
    EXPECT_NE(bare.out.find("\nfeatures             none\n"), std::string::npos) << bare.out;
}

TEST(PtRenderCli, ExportWritesSceneJsonThatLoadsAgain) {
    const std::string out = test::tempDir() + "/exported.json";
    const auto r = runCli("export " + cornell() + " -o " + out + " --quiet");
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const LoadResult reloaded = loadScene(out);
    ASSERT_TRUE(reloaded.ok()) << reloaded.error;
    EXPECT_EQ(reloaded.scene->instances.size(), 8u);
}

TEST(PtRenderCli, ExportsAGltfModelAsSceneJson) {
    const std::string out = test::tempDir() + "/knot.json";
    const auto r =
        runCli("export '" + test::projectPath("scenes/models/torus_knot.gltf") + "' -o " + out + " --quiet");
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const LoadResult reloaded = loadScene(out);
    ASSERT_TRUE(reloaded.ok()) << reloaded.error;
    EXPECT_EQ(reloaded.scene->triangleCount(), 12288u);
}

}  // namespace
}  // namespace pt

namespace pt {
namespace {

// `pt-render COMMAND --help` (or -h, anywhere among its arguments) prints that command's usage
// and the option groups it takes, and exits 0 without running it (issue 17: each said "see
// --help" and exited 2).
TEST(PtRenderCli, EachCommandAnswersHelpWithItsOwnUsage) {
    const struct {
        const char* command;
        bool toggles, display;
    } commands[] = {{"render", true, true},     {"bench", true, false},   {"reference", true, false},
                    {"converge", false, false}, {"stress", false, false}, {"export", false, false},
                    {"info", false, false},     {"gen", false, false}};
    for (const auto& c : commands) {
        const std::string name = c.command;
        for (const std::string& flag : {std::string(" --help"), std::string(" scene.json -h")}) {
            const auto r = runCli(name + flag);
            EXPECT_EQ(r.exitCode, 0) << name << flag << ": " << r.err;
            EXPECT_EQ(r.out.rfind("usage: pt-render " + name + " [options]\n\n  " + name + " ", 0), 0u)
                << r.out;
            EXPECT_EQ(r.out.find("TOGGLES:") != std::string::npos, c.toggles) << name;
            EXPECT_EQ(r.out.find("DISPLAY (") != std::string::npos, c.display) << name;
            for (const auto& other : commands) {  // no other command's usage line
                if (std::string(other.command) != name) {
                    EXPECT_EQ(r.out.find("\n  " + std::string(other.command) + " "), std::string::npos)
                        << name << " prints " << other.command;
                }
            }
        }
    }
    const auto unknown = runCli("frobnicate --help");
    EXPECT_EQ(unknown.exitCode, 2);
    EXPECT_NE(unknown.err.find("unknown command \"frobnicate\""), std::string::npos) << unknown.err;
    const auto usageError = runCli("info");
    EXPECT_EQ(usageError.exitCode, 2);
    EXPECT_NE(usageError.err.find("(see pt-render info --help)"), std::string::npos) << usageError.err;
}

// info lists each object's material variants (glTF KHR_materials_variants), so a user knows
// the names scene JSON's "variant" takes.
TEST(PtRenderCli, InfoListsMaterialVariants) {
    const auto r = runCli("info --json '" + test::testDataPath("gltf/variants.gltf") + "'");
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const auto info = nlohmann::json::parse(r.out);
    ASSERT_TRUE(info.contains("material_variants")) << r.out;
    EXPECT_EQ(info["material_variants"].size(), 1u);
    EXPECT_EQ(info["material_variants"].begin().value(),
              (std::vector<std::string>{"Leather", "Linen", "variant 2"}));
}

// Which glTF extensions a file declares and whether they are honoured (issue 18), as JSON and as
// one line.
TEST(PtRenderCli, InfoListsTheGltfExtensionsAndWhetherTheyAreHonoured) {
    const std::string path = "'" + test::testDataPath("gltf/primitive_extensions.gltf") + "'";
    const auto r = runCli("info --json " + path);
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const auto info = nlohmann::json::parse(r.out);
    ASSERT_TRUE(info.contains("gltf_extensions")) << r.out;
    EXPECT_EQ(info["gltf_extensions"]["KHR_materials_variants"], "honoured");
    EXPECT_EQ(info["gltf_extensions"].size(), 2u);
    const auto text = runCli("info --quiet " + path);
    EXPECT_NE(text.out.find("KHR_materials_variants"), std::string::npos) << text.out;
    EXPECT_EQ(runCli("info --json " + cornell()).out.find("gltf_extensions"), std::string::npos)
        << "a scene without model files lists none";
}

// The material extensions read last (issue 18) are listed as honoured, with the features they
// turn on, for the scene that shows them (scenes/extensions.json).
TEST(PtRenderCli, InfoListsAnisotropyIridescenceAndDispersionAsHonoured) {
    const auto r = runCli("info --json '" + test::projectPath("scenes/extensions.json") + "'");
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const auto info = nlohmann::json::parse(r.out);
    for (const char* name :
         {"KHR_materials_anisotropy", "KHR_materials_iridescence", "KHR_materials_dispersion",
          "KHR_materials_sheen", "KHR_materials_diffuse_transmission"})
        EXPECT_EQ(info["gltf_extensions"][name], "honoured") << name << ": " << r.out;
    const auto features = info["features"].get<std::vector<std::string>>();
    for (const char* feature : {"anisotropy", "iridescence", "dispersion"})
        EXPECT_NE(std::find(features.begin(), features.end(), feature), features.end())
            << feature << ": " << r.out;
    EXPECT_EQ(info["warnings"], 0) << r.err;
}

// OpenImageIO (about 260 shared libraries) is loaded on the first image read or written, not at
// start-up (issue 17: every start took 0.2-0.75 s, --help included). The dynamic loader's own
// log (LD_DEBUG=files) says which libraries a run opened.
TEST(PtRenderCli, OpenImageIoIsLoadedOnlyByRunsThatTouchImages) {
    if (!PT_TEST_HAVE_OIIO) GTEST_SKIP() << "built without OpenImageIO (PT_OIIO=OFF)";
    setenv("LD_DEBUG", "files", 1);
    const auto help = runCli("--help");
    const auto info = runCli("info " + cornell());
    const std::string exr = test::tempDir() + "/lazy_oiio.exr";
    const auto render = runCli("render " + cornell() + " --size 8x8 --spp 1 -o '" + exr + "'");
    unsetenv("LD_DEBUG");
    for (const auto* r : {&help, &info, &render}) EXPECT_EQ(r->exitCode, 0) << r->err.substr(0, 2000);
    EXPECT_EQ(help.err.find("libOpenImageIO"), std::string::npos);
    EXPECT_EQ(info.err.find("libOpenImageIO"), std::string::npos);
    EXPECT_NE(render.err.find("libOpenImageIO"), std::string::npos)
        << "the EXR writer ran without OpenImageIO?";
    EXPECT_TRUE(fs::file_size(exr) > 0);
}

}  // namespace
}  // namespace pt

namespace pt {
namespace {

// Runs pt-render with `args` (no shell), sends it SIGINT after `seconds`, and returns its exit
// code (-1 where a signal ended it); stderr goes to `errPath`. `seconds` after the signal ends
// it regardless, which fails the caller's checks.
int interruptedExitCode(std::vector<std::string> args, double seconds, const std::string& errPath) {
    args.insert(args.begin(), PT_RENDER_CLI);
    std::vector<char*> argv;
    for (std::string& w : args) argv.push_back(w.data());
    argv.push_back(nullptr);
    posix_spawn_file_actions_t files;
    posix_spawn_file_actions_init(&files);
    posix_spawn_file_actions_addopen(&files, 2, errPath.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    pid_t pid = 0;
    const int spawned = posix_spawn(&pid, argv[0], &files, nullptr, argv.data(), environ);
    posix_spawn_file_actions_destroy(&files);
    if (spawned != 0) return -2;
    std::this_thread::sleep_for(std::chrono::duration<double>(seconds));
    kill(pid, SIGINT);
    for (int waited = 0; waited < 300; ++waited) {  // up to 30 s for it to write and exit
        int status = 0;
        if (waitpid(pid, &status, WNOHANG) == pid) return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
        std::this_thread::sleep_for(std::chrono::milliseconds(100));
    }
    kill(pid, SIGKILL);
    waitpid(pid, nullptr, 0);
    return -1;
}

// Ctrl-C during a long render stops it between batches, writes the samples taken so far (the
// stats give their count) and exits 130, the shell's code for SIGINT (issue 17: every sample
// was thrown away).
TEST(PtRenderCli, CtrlCWritesTheSamplesRenderedSoFar) {
    const std::string dir = test::tempDir();
    const std::string png = dir + "/interrupted.png", stats = dir + "/interrupted.json",
                      err = dir + "/render.err";
    EXPECT_EQ(interruptedExitCode({"render", test::projectPath("scenes/cornell.json"), "--png", png,
                                   "--stats", stats, "--time", "120", "--size", "32x32", "--quiet"},
                                  3.0, err),
              130)
        << test::readTextFile(err);
    std::ifstream in(stats);
    ASSERT_TRUE(in.good()) << "no stats written";
    const nlohmann::json j = nlohmann::json::parse(in);
    EXPECT_GT(j["spp"].get<int>(), 0);
    EXPECT_TRUE(fs::exists(png));
    EXPECT_GT(fs::file_size(png), 100u);
}

// Ctrl-C during `reference` drops the batch under way and writes the finished ones, whose
// count it reports; the image is their mean.
TEST(PtRenderCli, CtrlCDuringAReferenceWritesTheFinishedBatches) {
    const std::string dir = test::tempDir();
    const std::string pfm = dir + "/interrupted.pfm", err = dir + "/reference.err";
    EXPECT_EQ(interruptedExitCode({"reference", test::projectPath("scenes/cornell.json"), "-o", pfm, "--spp",
                                   "200000", "--batches", "1000", "--size", "16x16", "--quiet"},
                                  3.0, err),
              130);
    const std::string message = test::readTextFile(err);
    const size_t at = message.find("interrupted: wrote the ");
    ASSERT_NE(at, std::string::npos) << message;
    const int batches = std::stoi(message.substr(at + std::string("interrupted: wrote the ").size()));
    EXPECT_GE(batches, 2);
    EXPECT_LT(batches, 1000);
    EXPECT_NE(message.find("(" + std::to_string(batches * 200) + " spp)"), std::string::npos) << message;
    EXPECT_TRUE(fs::exists(pfm));
    EXPECT_GT(fs::file_size(pfm), 16u * 16u * 3u * 4u);  // 16x16 RGB floats and a header
}

// Ctrl-C during `converge` ends the variant under way with the points it has, skips the rest,
// and still writes the CSV and prints the summary of what was measured.
TEST(PtRenderCli, CtrlCDuringConvergeKeepsWhatWasMeasured) {
    const std::string dir = test::tempDir();
    const std::string csv = dir + "/interrupted.csv", err = dir + "/converge.err";
    EXPECT_EQ(
        interruptedExitCode({"converge", test::projectPath("scenes/cornell.json"), "--reference-constant",
                             "0.5,0.5,0.5", "--time", "60", "--size", "16x16", "--variant", "first",
                             "--variant", "second:nee=off", "--csv", csv, "--quiet"},
                            3.0, err),
        130);
    EXPECT_NE(test::readTextFile(err).find("interrupted: measured 1 of 2 variants"), std::string::npos)
        << test::readTextFile(err);
    const std::string table = test::readTextFile(csv);
    EXPECT_EQ(table.rfind("variant,seconds,spp,relmse,rmse,mape\n", 0), 0u) << table.substr(0, 200);
    EXPECT_NE(table.find("\nfirst,"), std::string::npos) << table.substr(0, 200);
    EXPECT_EQ(table.find("\nsecond,"), std::string::npos);
}

}  // namespace
}  // namespace pt

namespace pt {
namespace {

// Where the CUDA backend cannot run, the error says why without quoting where the binary was
// built (issue 17: it named a source path of the build machine). Skips where a GPU renders.
TEST(PtRenderCli, ACudaFailureNamesNoBuildPath) {
    const std::string png = test::tempDir() + "/cuda.png";
    const auto r =
        runCli("render " + cornell() + " --backend cuda --png " + png + " --spp 1 --size 8x8 --quiet");
    if (r.exitCode == 0) GTEST_SKIP() << "a usable GPU rendered the scene";
    EXPECT_EQ(r.exitCode, 1) << r.err;
    const std::string sourceDir = fs::path(test::projectPath("render")).parent_path().string();
    EXPECT_EQ(r.err.find(sourceDir + "/"), std::string::npos) << r.err;
    EXPECT_EQ(r.err.rfind("pt-render render: ", 0), 0u) << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << "one line: " << r.err;
}

}  // namespace
}  // namespace pt
