// pt-render bench on the CPU backend (the GPU figures are taken on a GPU machine): it runs
// every section, writes its JSON atomically, and refuses what it cannot honour.
#include <gtest/gtest.h>

#include <fstream>
#include <iostream>
#include <map>
#include <nlohmann/json.hpp>
#include <set>

#include "app/cli_runner.h"
#include "render/backend/toggle_table.h"
#include "support/test_paths.h"

namespace pt {
namespace {

using test::runCli;

std::string cornell() { return "'" + test::projectPath("scenes/cornell.json") + "'"; }

TEST(PtRenderBench, MeasuresEverySectionAndWritesJson) {
    const std::string json = test::tempDir() + "/bench.json";
    const auto r = runCli("bench " + cornell() + " --size 24x16 --runs 2 --spp 1 --quiet --json " + json);
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_NE(r.out.find("median of 2 runs"), std::string::npos) << r.out;
    std::ifstream in(json);
    const nlohmann::json j = nlohmann::json::parse(in);
    EXPECT_EQ(j["backend"], "cpu");
    EXPECT_EQ(j["width"], 24);
    std::set<std::string> sections;
    std::map<std::string, double> value;      // "section/figure/variant"
    std::map<std::string, std::string> note;  // the same keys
    for (const auto& row : j["rows"]) {
        sections.insert(row["section"].get<std::string>());
        const std::string key = row["section"].get<std::string>() + "/" + row["figure"].get<std::string>() +
                                "/" + row["variant"].get<std::string>();
        value[key] = row["value"].get<double>();
        note[key] = row.value("note", std::string());
    }
    for (const char* s : {"scene", "rays", "path tracing", "BVH", "edit to first frame"}) {
        EXPECT_TRUE(sections.count(s)) << "missing section " << s;
    }
    // Every pixel's camera ray is traced, with the BVH and without (24 triangles are in budget).
    EXPECT_GT(value["rays/primary/BVH on"], 0.0);
    EXPECT_GT(value["rays/primary/BVH off"], 0.0);
    EXPECT_GT(value["path tracing/samples per pixel per second/default"], 0.0);
    EXPECT_GT(value["path tracing/samples per pixel per second/roulette off"], 0.0);
    // Edits go through the editor's session: command, sync, one pass, the frame for display.
    EXPECT_GT(value["edit to first frame/material (roughness slider)/samples done"], 0.0);
    EXPECT_GE(value["edit to first frame/material (roughness slider)/frame on host"],
              value["edit to first frame/material (roughness slider)/samples done"]);
    EXPECT_GT(value["edit to first frame/transform (object)/samples done"], 0.0);
    EXPECT_EQ(value["BVH/SAH cost vs CPU binned (CPU binned SAH)/"], 1.0);
    // The Embree baseline traces the same rays over the same triangles: every hit agrees.
    if (note.count("embree/baseline/")) {
        std::cout << "[ note     ] no Embree baseline: " << note["embree/baseline/"] << "\n";
    } else {
        for (const char* set : {"primary", "diffuse bounce", "shadow (any hit)"}) {
            const std::string key = std::string("embree/") + set + "/Embree, single rays";
            EXPECT_GT(value[key], 0.0) << key;
            EXPECT_EQ(note[key], "hits agree with ours on 100.000% of rays") << key;
            EXPECT_GT(value[std::string("embree/") + set + "/ours / Embree's best"], 0.0) << set;
        }
        EXPECT_GT(value["embree/BLAS build rate, ours / Embree/"], 0.0);
    }
}

// A scene with animations gets per-frame update figures: pose and sync, with each step.
TEST(PtRenderBench, TimesAnimatedFrames) {
    const std::string scene = "'" + test::testDataPath("gltf/skin_lift.gltf") + "'";
    const std::string json = test::tempDir() + "/bench_animation.json";
    const auto r = runCli("bench " + scene + " --size 16x16 --runs 1 --spp 1 --quiet --json " + json);
    ASSERT_EQ(r.exitCode, 0) << r.err;
    std::ifstream in(json);
    const nlohmann::json j = nlohmann::json::parse(in);
    std::map<std::string, nlohmann::json> rows;
    for (const auto& row : j["rows"]) {
        if (row["section"] == "animation")
            rows[row["figure"].get<std::string>() + "/" + row["variant"].get<std::string>()] = row;
    }
    ASSERT_TRUE(rows.count("frame update (pose + sync)/skin on host")) << r.out;
    const nlohmann::json& update = rows["frame update (pose + sync)/skin on host"];
    EXPECT_GT(update["value"].get<double>(), 0.0);
    EXPECT_NE(update.value("note", std::string()).find("12 frames at 30 fps, 4 skinned vertices; 12 refit"),
              std::string::npos)
        << update["note"];
    EXPECT_TRUE(rows.count("refit BLAS/skin on host")) << "each sync step has its row";
}

TEST(PtRenderBench, RejectsContradictoryToggles) {
    const auto r = runCli("bench " + cornell() + " --megakernel --wavefront");
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_NE(r.err.find("exclude each other"), std::string::npos) << r.err;
    const auto ratio = runCli("render " + cornell() + " --png x.png --rebuild-ratio 0.5");
    EXPECT_EQ(ratio.exitCode, 2);
    EXPECT_NE(ratio.err.find("--rebuild-ratio"), std::string::npos) << ratio.err;
}

TEST(PtRenderBench, ReportsTheTogglesInRenderStats) {
    const std::string dir = test::tempDir();
    const auto r = runCli("render " + cornell() + " --png " + dir + "/t.png --stats " + dir +
                          "/t.json --spp 1 --size 8x8 --quiet --no-jitter --no-rr");
    ASSERT_EQ(r.exitCode, 0) << r.err;
    std::ifstream in(dir + "/t.json");
    const nlohmann::json j = nlohmann::json::parse(in);
    EXPECT_EQ(j["toggles"]["rr"]["on"], false);
    EXPECT_EQ(j["toggles"]["pixel_jitter"]["on"], false);
    EXPECT_EQ(j["toggles"]["nee"]["on"], true);
    // The CPU backend says why it has no GPU scheduling.
    EXPECT_EQ(j["toggles"]["megakernel"]["active"], false);
    EXPECT_NE(j["toggles"]["megakernel"]["note"].get<std::string>().find("CUDA only"), std::string::npos);
}

// Every flag of the toggle table reaches its toggle, and only it: one render per flag, whose
// stats report each key as the defaults say except the one the flag names.
TEST(PtRenderBench, EveryToggleFlagSetsItsToggle) {
    const std::string dir = test::tempDir();
    const IntegratorToggles defaults;
    for (const ToggleRow& row : toggleTable()) {
        for (const bool on : {true, false}) {
            const std::string flag = on ? row.onFlag : row.offFlag;
            if (flag.empty()) continue;
            SCOPED_TRACE(flag);
            const auto r = runCli("render " + cornell() + " --png " + dir + "/f.png --stats " + dir +
                                  "/f.json --spp 1 --size 8x8 --quiet " + flag);
            ASSERT_EQ(r.exitCode, 0) << r.err;
            std::ifstream in(dir + "/f.json");
            const nlohmann::json j = nlohmann::json::parse(in);
            for (const ToggleRow& other : toggleTable()) {
                bool expected = other.id == row.id ? on : other.get(defaults);
                // Naming a schedule turns the auto schedule off.
                if (other.id == ToggleId::AutoSchedule && row.id == ToggleId::Megakernel) expected = false;
                EXPECT_EQ(j["toggles"][other.key]["on"], expected) << other.key;
            }
        }
    }
}

}  // namespace
}  // namespace pt
