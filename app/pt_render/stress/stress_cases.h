#pragma once
// The cases of `pt-render stress` (docs/robustness.md explains each, its expectation and the
// bug it guards). A case renders what it needs through the runner and returns its outcome.
#include <functional>
#include <string>
#include <vector>

#include "pt_render/stress/stress_expectation.h"
#include "pt_render/stress/stress_runner.h"

namespace pt::cli {

struct StressCase {
    std::string group;  // scale, geometry, materials, lights, accumulation, camera
    std::string name;
    std::string expectation;  // one line, as the table prints it
    std::function<StressOutcome(StressRunner&)> run;
    // A failure the renderer is known to have today, described here: the table shows it as
    // "known" and it does not fail the run; once the case passes it shows "fixed?".
    std::string knownIssue = {};
};

const std::vector<StressCase>& stressCases();

}  // namespace pt::cli
