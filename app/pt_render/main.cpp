// pt-render: the headless command line of the path tracer.
#include <cstdio>
#include <exception>
#include <string>
#include <vector>

#include "cli_options.h"
#include "commands.h"

namespace {

constexpr const char* kUsage = R"(usage: pt-render <command> [options]

commands:
  render SCENE -o OUT.exr [--png OUT.png] [--spp N | --time SECONDS] [--size WxH]
                [--seed N] [--threads N] [--backend cpu|cuda] [--stats STATS.json] [--quiet]
                [--max-depth N] [--no-nee] [--no-mis] [--no-rr] [--clamp X] [--bvh-off]
      Render SCENE (.json, .gltf, .glb or .obj) progressively; write a linear EXR and/or a
      display-referred PNG. Prints the paths it wrote.
  export SCENE -o OUT.json
      Write any loadable scene as scene JSON (atomically; defaults left out).
  info SCENE [--json]
      Triangles, meshes, instances, materials, textures, lights, bounds, load and BVH times.
)";

}  // namespace

int main(int argc, char** argv) {
    std::vector<std::string> args(argv + 1, argv + argc);
    if (args.empty() || args[0] == "-h" || args[0] == "--help" || args[0] == "help") {
        std::fputs(kUsage, args.empty() ? stderr : stdout);
        return args.empty() ? 2 : 0;
    }
    const std::string command = args[0];
    args.erase(args.begin());
    try {
        if (command == "render") return pt::cli::runRender(args);
        if (command == "export") return pt::cli::runExport(args);
        if (command == "info") return pt::cli::runInfo(args);
        std::fprintf(stderr, "pt-render: unknown command \"%s\" (render, export, info; see --help)\n",
                     command.c_str());
        return 2;
    } catch (const pt::cli::UsageError& e) {
        std::fprintf(stderr, "pt-render %s: %s (see --help)\n", command.c_str(), e.what());
        return 2;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "pt-render %s: %s\n", command.c_str(), e.what());
        return 1;
    }
}
