#include "pt_render/stress/stress_table.h"

#include "cli/output_paths.h"

namespace pt::cli {

namespace {

// CSV cells with commas or quotes are quoted, quotes doubled (RFC 4180).
std::string csvCell(const std::string& text) {
    if (text.find_first_of(",\"\n") == std::string::npos) return text;
    std::string quoted = "\"";
    for (char c : text) quoted += c == '"' ? std::string("\"\"") : std::string(1, c);
    return quoted + "\"";
}

}  // namespace

void printStressTable(std::FILE* out, const std::vector<StressRow>& rows) {
    std::fprintf(out, "%-13s %-31s %-7s %9s %11s %11s %-5s %7s  %s\n", "group", "case", "backend",
                 "nonfinite", "error", "bound", "", "seconds", "expectation");
    size_t failed = 0, known = 0;
    for (const StressRow& r : rows) {
        const bool passed = r.outcome.passed();
        failed += r.failsRun() ? 1 : 0;
        known += !passed && !r.failsRun() ? 1 : 0;
        const char* result =
            r.knownIssue.empty() ? (passed ? "pass" : "FAIL") : (passed ? "fixed?" : "known");
        std::fprintf(out, "%-13s %-31s %-7s %9llu %11.3g %11.3g %-5s %7.2f  %s\n", r.group.c_str(),
                     r.name.c_str(), r.backend.c_str(),
                     static_cast<unsigned long long>(r.outcome.nonfiniteSamples), r.outcome.error,
                     r.outcome.bound, result, r.seconds, r.expectation.c_str());
        if (!r.outcome.note.empty() && !passed) std::fprintf(out, "%-13s   %s\n", "", r.outcome.note.c_str());
        if (!r.knownIssue.empty()) std::fprintf(out, "%-13s   known issue: %s\n", "", r.knownIssue.c_str());
    }
    std::fprintf(out, "%zu of %zu passed", rows.size() - failed - known, rows.size());
    if (known) std::fprintf(out, ", %zu known issue%s", known, known > 1 ? "s" : "");
    std::fprintf(out, "%s\n", failed ? ", FAILED" : "");
}

std::string stressCsv(const std::vector<StressRow>& rows) {
    std::string csv =
        "group,case,backend,nonfinite_samples,error,bound,result,seconds,expectation,note,known_issue\n";
    for (const StressRow& r : rows) {
        csv += csvCell(r.group) + "," + csvCell(r.name) + "," + r.backend + "," +
               std::to_string(r.outcome.nonfiniteSamples) + "," + formatFigure(r.outcome.error) + "," +
               formatFigure(r.outcome.bound) + "," +
               (r.outcome.passed()     ? "pass"
                : r.knownIssue.empty() ? "fail"
                                       : "known") +
               "," + formatFigure(r.seconds) + "," + csvCell(r.expectation) + "," + csvCell(r.outcome.note) +
               "," + csvCell(r.knownIssue) + "\n";
    }
    return csv;
}

}  // namespace pt::cli
