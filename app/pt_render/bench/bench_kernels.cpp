#include "pt_render/bench/bench_kernels.h"

#include <unistd.h>

#include <cstdio>
#include <map>
#include <regex>
#include <string>

#include "render/compile/scene_features.h"

namespace pt::cli {

namespace {

// Instruction count of every kernel in this executable's machine code, by mangled name, from
// `cuobjdump -sass` (the CUDA toolkit's disassembler: on the PATH, else in the toolkit's usual
// place); empty where there is none.
std::map<std::string, int> sassInstructionCounts() {
    std::map<std::string, int> counts;
    // This executable's own path: /proc/self in the shell popen starts would be the shell's.
    char exe[4096];
    const ssize_t length = readlink("/proc/self/exe", exe, sizeof(exe) - 1);
    if (length <= 0) return counts;
    exe[length] = '\0';
    const std::string path = "'" + std::string(exe) + "'";
    const std::string command = "{ command -v cuobjdump >/dev/null && cuobjdump -sass " + path +
                                " || /usr/local/cuda/bin/cuobjdump -sass " + path + "; } 2>/dev/null";
    std::FILE* pipe = popen(command.c_str(), "r");
    if (!pipe) return counts;
    static const std::regex function(R"(Function\s*:\s*(\S+))");
    static const std::regex instruction(R"(^\s*/\*[0-9a-f]{4,}\*/\s+\S)");
    std::string current;
    char line[4096];
    while (std::fgets(line, sizeof(line), pipe)) {
        std::cmatch m;
        if (std::regex_search(line, m, function)) {
            current = m[1].str();
            counts[current] = 0;
        } else if (!current.empty() && std::regex_search(line, instruction)) {
            ++counts[current];
        }
    }
    pclose(pipe);
    return counts;
}

}  // namespace

void benchKernelVariants(const Backend& backend, BenchReport& report) {
    const KernelFigures figures = backend.kernelFigures();
    for (const KernelVariantFigures& v : figures.variants) {
        report.add({"kernels", "variant features", v.name, double(featureNames(v.features).size()),
                    "features", v.features == kAllFeatures ? "all" : describeFeatures(v.features)});
    }
    if (figures.kernels.empty()) return;
    const std::map<std::string, int> instructions = sassInstructionCounts();
    for (const KernelResources& k : figures.kernels) {
        const std::string variant = k.variant + ", " + k.kernel;
        report.add({"kernels", "registers per thread", variant, double(k.registers), "", ""});
        report.add(
            {"kernels", "local memory (stack, spills)", variant, double(k.localBytes), "bytes/thread", ""});
        const auto found = instructions.find(k.symbol);
        report.add({"kernels", "instructions (SASS)", variant,
                    found != instructions.end() ? double(found->second) : 0.0, "",
                    found != instructions.end() ? "" : "no cuobjdump, or the symbol is not in its output"});
    }
}

}  // namespace pt::cli
