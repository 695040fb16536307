// pt-render gen: synthetic glTF scenes at sizes no shared asset reaches, for measuring BVH
// build and trace rates: a displaced sphere of up to 10 million triangles (with --morph, a
// morph target for timing weight edits), the same skinned into an animated column (per-frame
// skinning and refit), or a field of up to a million instances of one mesh.
#include <algorithm>
#include <cctype>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <stdexcept>

#include "cli/cli_options.h"
#include "cli/progress_bar.h"
#include "pt_render/commands.h"
#include "pt_render/gen/gen_field.h"
#include "pt_render/gen/gen_gltf_writer.h"
#include "pt_render/gen/gen_skinned.h"
#include "pt_render/gen/gen_source_mesh.h"
#include "pt_render/gen/gen_sphere.h"

namespace pt::cli {

namespace {

constexpr uint32_t kMaxSphereTriangles = 10'000'000;
constexpr uint32_t kMaxFieldInstances = 1'000'000;
constexpr uint32_t kFieldSphereTriangles = 1000;

struct GenOutput {
    std::string gltfPath;
    uint64_t seed = 0;
    bool quiet = false;
};

GenOutput parseOutput(const Options& o) {
    GenOutput out;
    out.gltfPath = o.value("-o").value_or("");
    if (out.gltfPath.empty()) throw UsageError("give the output: -o OUT.gltf");
    std::string extension = std::filesystem::path(out.gltfPath).extension().string();
    std::transform(extension.begin(), extension.end(), extension.begin(),
                   [](unsigned char c) { return char(std::tolower(c)); });
    if (extension != ".gltf") throw UsageError("-o: expected a .gltf path, got \"" + out.gltfPath + "\"");
    out.seed = o.nonNegativeInt("--seed").value_or(0);
    out.quiet = o.has("--quiet");
    return out;
}

// The kind (sphere, skinned or field) is the only positional argument.
void checkPositional(const Options& o) {
    if (o.positional().size() > 1) throw UsageError("unexpected argument \"" + o.positional()[1] + "\"");
}

// --displace: a number in [0, 1); 1 or more would pass the surface through the centre.
double parseAmplitude(const Options& o) {
    const auto v = o.value("--displace");
    if (!v) return 0.1;
    char* end = nullptr;
    const double a = std::strtod(v->c_str(), &end);
    if (v->empty() || *end != '\0' || !(a >= 0.0 && a < 1.0)) {
        throw UsageError("--displace: expected a number in [0, 1), got \"" + *v + "\"");
    }
    return a;
}

// Fails before generating, not after, when the output cannot be written.
void checkOutputFolder(const std::string& path) {
    const std::filesystem::path folder = std::filesystem::path(path).parent_path();
    if (!folder.empty() && !std::filesystem::is_directory(folder)) {
        throw std::runtime_error(path + ": folder " + folder.string() + " does not exist");
    }
}

// Writes OUT.gltf and OUT.bin and lists them on stdout.
void writeAndList(const GenScene& scene, const GenOutput& out, ProgressBar& bar) {
    writeGenGltf(scene, out.gltfPath, bar.callback());
    bar.finish();
    std::printf("%s\n%s\n", out.gltfPath.c_str(), binPathFor(out.gltfPath).c_str());
}

int runSphere(const std::vector<std::string>& args) {
    const Options o(args, {"-o", "--triangles", "--displace", "--seed"}, {"--quiet", "--morph"});
    checkPositional(o);
    const GenOutput out = parseOutput(o);
    const auto triangles = o.positiveInt("--triangles");
    if (!triangles) throw UsageError("give the size: --triangles N");
    if (*triangles > kMaxSphereTriangles) throw UsageError("--triangles: at most 10000000");
    const double amplitude = parseAmplitude(o);
    checkOutputFolder(out.gltfPath);

    ProgressBar bar(!out.quiet);
    GenScene scene;
    scene.mesh = generateDisplacedSphere({*triangles, amplitude, out.seed}, bar.callback());
    const bool morph = o.has("--morph");
    if (morph) addBulgeTarget(scene.mesh);
    scene.instances.push_back(GenNode{});
    // Framed whole at every weight from 0 to 1 of the bulge.
    const float reach = float(1.0 + amplitude) * (morph ? 1.0f + kBulgeAmplitude : 1.0f);
    scene.camera = frameSphere(Vec3(0.0f), reach, Vec3(0.35f, 0.45f, 1.0f));
    scene.lights = defaultLights();
    writeAndList(scene, out, bar);
    std::printf("%zu triangles, %zu vertices, 1 instance%s\n", scene.mesh.indices.size() / 3,
                scene.mesh.positions.size(), morph ? ", morph target \"bulge\" (weight 0)" : "");
    return 0;
}

int runSkinned(const std::vector<std::string>& args) {
    const Options o(args, {"-o", "--triangles", "--displace", "--joints", "--seed"}, {"--quiet"});
    checkPositional(o);
    const GenOutput out = parseOutput(o);
    const auto triangles = o.positiveInt("--triangles");
    if (!triangles) throw UsageError("give the size: --triangles N");
    if (*triangles > kMaxSphereTriangles) throw UsageError("--triangles: at most 10000000");
    SkinnedSpec spec;
    spec.targetTriangles = *triangles;
    spec.amplitude = parseAmplitude(o);
    spec.seed = out.seed;
    spec.joints = o.positiveInt("--joints").value_or(spec.joints);
    if (spec.joints < 2 || spec.joints > 256) throw UsageError("--joints: from 2 to 256");
    checkOutputFolder(out.gltfPath);

    ProgressBar bar(!out.quiet);
    const GenScene scene = generateSkinnedColumn(spec, bar.callback());
    writeAndList(scene, out, bar);
    std::printf("%zu triangles, %zu vertices, %u joints, animation \"%s\" (%g s, looping)\n",
                scene.mesh.indices.size() / 3, scene.mesh.positions.size(), spec.joints,
                scene.skin->animation.c_str(), double(spec.periodSeconds));
    return 0;
}

int runField(const std::vector<std::string>& args) {
    const Options o(args, {"-o", "--count", "--mesh", "--spacing", "--seed"}, {"--quiet"});
    checkPositional(o);
    const GenOutput out = parseOutput(o);
    const auto count = o.positiveInt("--count");
    if (!count) throw UsageError("give the size: --count N");
    if (*count > kMaxFieldInstances) throw UsageError("--count: at most 1000000");
    const FieldSpec spec{*count, o.positiveNumber("--spacing"), out.seed};
    checkOutputFolder(out.gltfPath);

    ProgressBar bar(!out.quiet);
    GenScene scene;
    if (const auto mesh = o.value("--mesh")) {
        scene.mesh = loadMergedMesh(*mesh, kMaxSphereTriangles, bar.callback());
    } else {
        scene.mesh = generateDisplacedSphere({kFieldSphereTriangles, 0.1, out.seed}, bar.callback());
    }
    bar.finish();
    FieldLayout layout = layoutField(scene.mesh, spec);
    scene.instances = std::move(layout.instances);
    scene.camera = frameBox(layout.lo, layout.hi, Vec3(0.0f, 0.7f, 1.0f));
    scene.lights = defaultLights();
    writeAndList(scene, out, bar);
    const uint64_t meshTriangles = scene.mesh.indices.size() / 3;
    std::printf("%llu triangles x %zu instances = %llu instanced triangles, spacing %g\n",
                static_cast<unsigned long long>(meshTriangles), scene.instances.size(),
                static_cast<unsigned long long>(meshTriangles * scene.instances.size()), layout.spacing);
    return 0;
}

}  // namespace

int runGen(const std::vector<std::string>& args) {
    const std::string kind = args.empty() ? "" : args[0];
    if (kind == "sphere") return runSphere(args);
    if (kind == "field") return runField(args);
    if (kind == "skinned") return runSkinned(args);
    throw UsageError(kind.empty() || kind[0] == '-'
                         ? "expected a kind: sphere, skinned or field"
                         : "unknown kind \"" + kind + "\" (sphere, skinned or field)");
}

}  // namespace pt::cli
