// pt-render: the headless command line of the path tracer.
#include <cstdio>
#include <exception>
#include <optional>
#include <string>
#include <vector>

#include "assets/message_text.h"
#include "cli/cli_options.h"
#include "pt_render/commands.h"
#include "pt_render/usage.h"

int main(int argc, char** argv) {
    std::vector<std::string> args(argv + 1, argv + argc);
    if (args.empty() || args[0] == "-h" || args[0] == "--help" || args[0] == "help") {
        std::fputs(pt::cli::fullUsage().c_str(), args.empty() ? stderr : stdout);
        return args.empty() ? 2 : 0;
    }
    const std::string command = args[0];
    args.erase(args.begin());
    if (const std::optional<std::string> usage = pt::cli::commandUsage(command);
        usage && pt::cli::asksForHelp(args)) {
        std::fputs(usage->c_str(), stdout);
        return 0;
    }
    try {
        if (command == "render") return pt::cli::runRender(args);
        if (command == "export") return pt::cli::runExport(args);
        if (command == "info") return pt::cli::runInfo(args);
        if (command == "gen") return pt::cli::runGen(args);
        if (command == "bench") return pt::cli::runBench(args);
        if (command == "reference") return pt::cli::runReference(args);
        if (command == "converge") return pt::cli::runConverge(args);
        if (command == "stress") return pt::cli::runStress(args);
        std::fprintf(stderr,
                     "pt-render: unknown command \"%s\" (render, bench, reference, converge, stress, export, "
                     "info, gen; "
                     "see --help)\n",
                     command.c_str());
        return 2;
    } catch (const pt::cli::UsageError& e) {
        std::fprintf(stderr, "pt-render %s: %s (see pt-render %s --help)\n", command.c_str(),
                     pt::oneLineMessage(e.what()).c_str(), command.c_str());
        return 2;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "pt-render %s: %s\n", command.c_str(), pt::oneLineMessage(e.what()).c_str());
        return 1;
    }
}
