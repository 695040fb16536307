// pt-render converge: CSV and SVG of error against time, the equal-time table, and the flag on
// a variant whose error stops falling.
#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <map>
#include <sstream>

#include "app/cli_runner.h"
#include "support/test_paths.h"

namespace pt {
namespace {

using test::runCli;

std::string scene(const std::string& relative) { return "'" + test::projectPath(relative) + "'"; }

std::string slurp(const std::string& path) {
    std::ifstream in(path);
    std::stringstream text;
    text << in.rdbuf();
    return text.str();
}

// The summary line of a variant in the equal-time table.
std::string summaryLine(const std::string& out, const std::string& variant) {
    std::istringstream lines(out);
    for (std::string line; std::getline(lines, line);) {
        if (line.rfind(variant + " ", 0) == 0) return line;
    }
    return "";
}

struct CsvRow {
    std::string variant;
    double seconds;
    unsigned spp;
    double relmse, rmse, mape;
};

std::vector<CsvRow> readCsv(const std::string& path, std::string& header) {
    std::ifstream in(path);
    std::getline(in, header);
    std::vector<CsvRow> rows;
    for (std::string line; std::getline(in, line);) {
        std::replace(line.begin(), line.end(), ',', ' ');
        std::istringstream cells(line);
        CsvRow r;
        cells >> r.variant >> r.seconds >> r.spp >> r.relmse >> r.rmse >> r.mape;
        EXPECT_FALSE(cells.fail()) << line;
        rows.push_back(r);
    }
    return rows;
}

// A white furnace has an exact answer (every pixel 1): an unbiased variant must converge at the
// Monte Carlo rate, with no reference noise to blur the judgement.
TEST(PtRenderConverge, WritesCsvAndSvgAndPassesAnUnbiasedVariant) {
    const std::string dir = test::tempDir();
    const auto r = runCli("converge " + scene("scenes/stress/furnace_diffuse.json") +
                          " --reference-constant 1,1,1 --size 16x16 --time 1.5 --variant full --variant "
                          "no-roulette:rr=off --csv " +
                          dir + "/f.csv --plot " + dir + "/f.svg --quiet");
    ASSERT_EQ(r.exitCode, 0) << r.err;
    std::string header;
    const std::vector<CsvRow> rows = readCsv(dir + "/f.csv", header);
    EXPECT_EQ(header, "variant,seconds,spp,relmse,rmse,mape");
    std::map<std::string, std::vector<CsvRow>> byVariant;
    for (const CsvRow& row : rows) byVariant[row.variant].push_back(row);
    ASSERT_EQ(byVariant.size(), 2u);
    for (const auto& [name, curve] : byVariant) {
        EXPECT_GE(curve.size(), 5u) << name;
        for (size_t i = 1; i < curve.size(); ++i) {
            EXPECT_GT(curve[i].seconds, curve[i - 1].seconds) << name;
            EXPECT_GE(curve[i].spp, curve[i - 1].spp) << name;
        }
        EXPECT_GE(curve.back().seconds, 1.5) << name;
        EXPECT_LT(curve.back().relmse, curve.front().relmse) << name;
    }
    EXPECT_NE(summaryLine(r.out, "full").find("converging"), std::string::npos) << r.out;
    EXPECT_NE(summaryLine(r.out, "no-roulette").find("converging"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("equal time"), std::string::npos) << r.out;

    const std::string svg = slurp(dir + "/f.svg");
    EXPECT_EQ(svg.rfind("<svg", 0), 0u);
    EXPECT_NE(svg.find("</svg>"), std::string::npos);
    size_t polylines = 0;
    for (size_t at = svg.find("<polyline"); at != std::string::npos; at = svg.find("<polyline", at + 1))
        ++polylines;
    EXPECT_EQ(polylines, 2u);
    for (const char* text : {">full<", ">no-roulette<", ">slope -1<", "class=\"guide\"", "10<tspan",
                             "render time (s)", ">relMSE<"}) {
        EXPECT_NE(svg.find(text), std::string::npos) << text;
    }
}

// A firefly clamp at 0.01 darkens the Cornell box for good: against an unclamped reference its
// error levels off, and the run must say so.
TEST(PtRenderConverge, FlagsABiasedVariant) {
    PT_REQUIRE_OIIO();
    const std::string dir = test::tempDir();
    const auto ref = runCli("reference " + scene("scenes/cornell.json") + " -o " + dir +
                            "/ref.exr --spp 256 --size 16x16 --quiet");
    ASSERT_EQ(ref.exitCode, 0) << ref.err;
    const auto r =
        runCli("converge " + scene("scenes/cornell.json") + " --reference " + dir +
               "/ref.exr --size 16x16 --time 1 --variant clamped:clamp=0.01 --csv " + dir + "/c.csv --quiet");
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_NE(summaryLine(r.out, "clamped").find("BIASED OR STUCK"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("reference noise"), std::string::npos) << r.out;
}

// denoise=on measures the denoised image: on the Cornell box its first points, at a few
// samples, have far less error than the raw image's at the same times.
TEST(PtRenderConverge, ADenoisedVariantMeasuresTheDenoisedImage) {
    PT_REQUIRE_OIIO();
    const std::string dir = test::tempDir();
    const auto ref = runCli("reference " + scene("scenes/cornell.json") + " -o " + dir +
                            "/ref.exr --spp 512 --size 32x32 --quiet");
    ASSERT_EQ(ref.exitCode, 0) << ref.err;
    const auto r =
        runCli("converge " + scene("scenes/cornell.json") + " --reference " + dir +
               "/ref.exr --size 32x32 --time 0.5 --variant raw --variant denoised:denoise=on --csv " + dir +
               "/d.csv --quiet");
    ASSERT_EQ(r.exitCode, 0) << r.err;
    std::string header;
    std::map<std::string, std::vector<CsvRow>> byVariant;
    for (const CsvRow& row : readCsv(dir + "/d.csv", header)) byVariant[row.variant].push_back(row);
    ASSERT_FALSE(byVariant["raw"].empty());
    ASSERT_FALSE(byVariant["denoised"].empty());
    const CsvRow &raw = byVariant["raw"].front(), &denoised = byVariant["denoised"].front();
    EXPECT_LT(denoised.relmse, 0.5 * raw.relmse)
        << "raw " << raw.spp << " spp, denoised " << denoised.spp << " spp";
}

TEST(PtRenderConverge, BadUsageExits2AndBadInput1) {
    const std::string furnace = scene("scenes/stress/furnace_diffuse.json");
    struct Case {
        std::string args;
        int code;
        std::string needle;
    };
    const Case cases[] = {
        {"converge " + furnace, 2, "--reference"},
        {"converge " + furnace + " --reference a.exr --reference-constant 1", 2, "--reference"},
        {"converge " + furnace + " --reference-constant 1,x,1", 2, "R,G,B"},
        {"converge " + furnace + " --reference-constant 1 --variant v:nee=maybe", 2, "nee"},
        {"converge " + furnace + " --reference-constant 1 --variant v:speed=11", 2, "unknown key"},
        {"converge " + furnace + " --reference-constant 1 --variant v:guide_samples=64", 2, "denoise=on"},
        {"converge " + furnace + " --reference-constant 1 --variant v:denoise=on,guide_samples=-1", 2,
         "guide_samples"},
        {"converge " + furnace + " --reference-constant 1 --variant a --variant a", 2, "two variants"},
        {"converge " + furnace + " --reference /nonexistent/ref.exr", 1, "/nonexistent/ref.exr"},
        {"converge /nonexistent/s.json --reference-constant 1", 1, "/nonexistent/s.json"},
    };
    for (const Case& c : cases) {
        const auto r = runCli(c.args + " --time 0.1");
        EXPECT_EQ(r.exitCode, c.code) << c.args << "\n" << r.err;
        EXPECT_NE(r.err.find(c.needle), std::string::npos) << c.args << "\n" << r.err;
        EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    }
}

TEST(PtRenderConverge, RefusesAReferenceOfAnotherSize) {
    PT_REQUIRE_OIIO();
    const std::string dir = test::tempDir();
    const std::string furnace = scene("scenes/stress/furnace_diffuse.json");
    ASSERT_EQ(
        runCli("reference " + furnace + " -o " + dir + "/small.exr --spp 8 --size 8x8 --quiet").exitCode, 0);
    const auto r =
        runCli("converge " + furnace + " --reference " + dir + "/small.exr --size 16x8 --time 0.1");
    EXPECT_EQ(r.exitCode, 1);
    EXPECT_NE(r.err.find("small.exr: the reference is 8x8 but the render is 16x8"), std::string::npos)
        << r.err;
}

}  // namespace
}  // namespace pt
