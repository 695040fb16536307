#pragma once
// The pt-render subcommands. Each takes the arguments after its name and returns the exit
// code: 0 success, 1 failure (bad input, failed write), 2 bad usage.
#include <string>
#include <vector>

namespace pt::cli {

int runRender(const std::vector<std::string>& args);
int runExport(const std::vector<std::string>& args);
int runInfo(const std::vector<std::string>& args);
int runGen(const std::vector<std::string>& args);
int runBench(const std::vector<std::string>& args);
int runReference(const std::vector<std::string>& args);
int runConverge(const std::vector<std::string>& args);
int runStress(const std::vector<std::string>& args);

}  // namespace pt::cli
