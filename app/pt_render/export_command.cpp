// pt-render export: any loadable scene to scene JSON.
#include <cstdio>

#include "assets/scene_json/scene_json.h"
#include "cli/cli_options.h"
#include "cli/scene_input.h"
#include "pt_render/commands.h"

namespace pt::cli {

int runExport(const std::vector<std::string>& args) {
    const Options o(args, {"-o"}, {"--quiet"});
    if (o.positional().size() != 1) throw UsageError("expected one SCENE argument");
    const auto output = o.value("-o");
    if (!output) throw UsageError("give the output: -o OUT.json");
    ProgressBar bar(!o.has("--quiet"));
    const SceneInput input = loadSceneInput(o.positional()[0], bar);
    writeSceneJson(input.scene, *output);
    std::printf("%s\n", output->c_str());
    return 0;
}

}  // namespace pt::cli
