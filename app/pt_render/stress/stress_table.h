#pragma once
// The results of `pt-render stress`: one row a case and backend, printed as a table and
// written as CSV.
#include <cstdio>
#include <string>
#include <vector>

#include "pt_render/stress/stress_expectation.h"

namespace pt::cli {

struct StressRow {
    std::string group, name, backend, expectation;
    StressOutcome outcome;
    double seconds = 0.0;
    std::string knownIssue;  // see StressCase::knownIssue
    // Fails the run: failed, and not a known issue.
    bool failsRun() const { return !outcome.passed() && knownIssue.empty(); }
};

void printStressTable(std::FILE* out, const std::vector<StressRow>& rows);
// group,case,backend,nonfinite_samples,error,bound,result (pass, fail,
// known),seconds,expectation,note,known_issue
std::string stressCsv(const std::vector<StressRow>& rows);

}  // namespace pt::cli
