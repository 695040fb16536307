#pragma once
// Runs the real pt-render executable and captures its exit code, stdout and stderr.
#include <string>

namespace pt::test {

struct CliResult {
    int exitCode = -1;
    std::string out, err;
};

// `args` is appended to the pt-render path as shell words (callers quote what needs it).
CliResult runCli(const std::string& args);

}  // namespace pt::test
