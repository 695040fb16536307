// Fuzz target: the scene JSON reader (every object, material, light, camera, environment and
// render key, transforms, material overrides) through loadScene, then the render compile. A
// scene that loads must also survive a round trip: written with sceneToJson and read back, it
// loads again (else the editor saves files it cannot reopen). Model files and textures the
// JSON names do not exist beside it, so objects referencing files fail to load; the model
// importers have targets of their own.
#include "assets/scene_json/scene_json.h"
#include "assets/scene_loader.h"
#include "fuzz_load.h"
#include "support/test_paths.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    const std::optional<pt::Scene> scene = pt::fuzz::loadAndCompile({"scene.json"}, data, size);
    if (!scene) return 0;
    const std::string path = pt::test::tempDir() + "/scene.json";
    const std::string written = pt::sceneToJson(*scene, path);
    const auto reread = pt::fuzz::loadAndCompile(
        {"scene.json"}, reinterpret_cast<const uint8_t*>(written.data()), written.size());
    if (!reread) {
        pt::fuzz::fail("a scene that loaded does not load after sceneToJson",
                       pt::loadScene(pt::test::writeTempFile("scene.json", written)).error +
                           "\n--- written:\n" + written);
    }
    return 0;
}
