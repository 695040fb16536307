// pt-render stress: the robustness suite (docs/robustness.md). Every case runs on every
// backend asked for, against a stated expectation; exit status 1 when any fails.
#include <cstdio>
#include <filesystem>
#include <stdexcept>

#include "assets/atomic_file.h"
#include "cli/cli_options.h"
#include "cli/output_paths.h"
#include "pt_render/commands.h"
#include "pt_render/stress/stress_cases.h"
#include "pt_render/stress/stress_table.h"
#include "render/util/stopwatch.h"

namespace pt::cli {

namespace {

struct StressRequest {
    std::vector<std::string> backends;
    bool quick = false;
    std::string csvPath, only, scenesFolder;
};

// The scenes folder: --scenes, else ./scenes when it has the suite, else the source tree's,
// found above this file's folder (compilers see it as an absolute path under CMake).
std::string scenesFolder(const std::optional<std::string>& given) {
    namespace fs = std::filesystem;
    if (given) return *given;
    if (fs::is_directory("scenes/stress")) return "scenes";
    for (fs::path up = fs::path(__FILE__).parent_path(); up.has_relative_path(); up = up.parent_path()) {
        if (fs::is_directory(up / "scenes" / "stress")) return (up / "scenes").string();
    }
    throw std::runtime_error("cannot find the scenes folder (scenes/stress); give it with --scenes DIR");
}

// "all": the CPU, and CUDA where a device is usable (else say why it is left out).
std::vector<std::string> backendsFor(const std::string& choice) {
    if (choice != "all") {
        createBackend(choice);  // throws, naming the backends there are or why CUDA is unusable
        return {choice};
    }
    try {
        createBackend("cuda");
        return {"cpu", "cuda"};
    } catch (const std::exception& e) {
        std::fprintf(stderr, "stress: cuda skipped: %s\n", e.what());
        return {"cpu"};
    }
}

StressRequest parseRequest(const std::vector<std::string>& args) {
    const Options o(args, {"--backend", "--csv", "--only", "--scenes"}, {"--quick"});
    if (!o.positional().empty()) throw UsageError("takes no positional arguments");
    StressRequest r;
    r.quick = o.has("--quick");
    r.csvPath = o.value("--csv").value_or("");
    r.only = o.value("--only").value_or("");
    r.scenesFolder = scenesFolder(o.value("--scenes"));
    r.backends = backendsFor(o.value("--backend").value_or("cpu"));
    return r;
}

// --only NAME,NAME: cases whose name or group contains one of them.
bool selected(const StressCase& c, const std::string& only) {
    if (only.empty()) return true;
    const std::string list = only + ",";
    for (size_t begin = 0, end; (end = list.find(',', begin)) != std::string::npos; begin = end + 1) {
        const std::string part = list.substr(begin, end - begin);
        if (!part.empty() && (c.name.find(part) != std::string::npos || c.group == part)) return true;
    }
    return false;
}

}  // namespace

int runStress(const std::vector<std::string>& args) {
    const StressRequest r = parseRequest(args);
    checkOutputFolder(r.csvPath);
    std::vector<StressRow> rows;
    for (const std::string& backend : r.backends) {
        StressRunner runner(backend, r.quick, r.scenesFolder);
        for (const StressCase& c : stressCases()) {
            if (!selected(c, r.only)) continue;
            StressRow row;
            row.group = c.group, row.name = c.name, row.backend = backend;
            row.expectation = c.expectation, row.knownIssue = c.knownIssue;
            const auto start = Clock::now();
            try {
                row.outcome = c.run(runner);
            } catch (const std::exception& e) {
                row.outcome.error = 1.0;
                row.outcome.note = std::string("FAIL: ") + e.what();
            }
            row.seconds = secondsSince(start);
            rows.push_back(std::move(row));
        }
    }
    if (rows.empty()) throw UsageError("--only " + r.only + ": no case matches");
    printStressTable(stdout, rows);
    if (!r.csvPath.empty()) writeTextAtomically(r.csvPath, stressCsv(rows));
    for (const StressRow& row : rows) {
        if (row.failsRun()) return 1;
    }
    return 0;
}

}  // namespace pt::cli
