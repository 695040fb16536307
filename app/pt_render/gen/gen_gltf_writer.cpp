#include "pt_render/gen/gen_gltf_writer.h"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <memory>
#include <nlohmann/json.hpp>
#include <stdexcept>

#include "assets/atomic_file.h"

namespace pt::cli {

namespace {

static_assert(sizeof(Vec3) == 12, "POSITION and NORMAL are written straight from Vec3 arrays");
static_assert(__BYTE_ORDER__ == __ORDER_LITTLE_ENDIAN__, "glTF buffers are little-endian");

constexpr int kFloat = 5126, kUnsignedInt = 5125, kUnsignedShort = 5123;
constexpr int kArrayBuffer = 34962, kElementArrayBuffer = 34963;

// One tightly packed array of the buffer (each a multiple of 4 bytes, so all stay 4-byte
// aligned), with the accessor that reads it: positions, normals, indices, then a skin's joints,
// weights and inverse bind matrices and its animation's key times and rotations, then each morph
// target's position deltas.
struct BinPart {
    const void* data = nullptr;
    uint64_t bytes = 0;
    uint64_t offset = 0;              // in the buffer
    nlohmann::ordered_json accessor;  // without its bufferView, the part's own
    int target = 0;                   // the bufferView's target; 0: none (not vertex data)
};

template <class T>
BinPart part(const std::vector<T>& array, const char* type, int componentType, int target = 0) {
    BinPart p;
    p.data = array.data();
    p.bytes = array.size() * sizeof(T);
    p.accessor = {{"componentType", componentType}, {"count", array.size()}, {"type", type}};
    p.target = target;
    return p;
}

// Vertex positions or their morph deltas, with the exact per-axis "min" and "max" that glTF
// requires of every POSITION accessor, morph targets' included.
BinPart positionPart(const std::vector<Vec3>& points) {
    Vec3 lo = points.empty() ? Vec3(0.0f) : points[0], hi = lo;
    for (const Vec3& p : points) {
        lo = vmin(lo, p);
        hi = vmax(hi, p);
    }
    BinPart p = part(points, "VEC3", kFloat, kArrayBuffer);
    p.accessor["min"] = {lo.x, lo.y, lo.z};
    p.accessor["max"] = {hi.x, hi.y, hi.z};
    return p;
}

// The buffer's parts in order, laid out end to end; accessor i reads part i.
std::vector<BinPart> binParts(const GenScene& scene) {
    static_assert(sizeof(std::array<uint16_t, 4>) == 8 && sizeof(std::array<float, 16>) == 64, "packed");
    const Mesh& mesh = scene.mesh;
    std::vector<BinPart> parts = {positionPart(mesh.positions),
                                  part(mesh.normals, "VEC3", kFloat, kArrayBuffer),
                                  part(mesh.indices, "SCALAR", kUnsignedInt, kElementArrayBuffer)};
    if (scene.skin) {
        const GenSkin& skin = *scene.skin;
        parts.push_back(part(skin.vertexJoints, "VEC4", kUnsignedShort, kArrayBuffer));
        parts.push_back(part(skin.vertexWeights, "VEC4", kFloat, kArrayBuffer));
        parts.push_back(part(skin.inverseBindMatrices, "MAT4", kFloat));
        parts.push_back(part(skin.keyTimes, "SCALAR", kFloat));
        parts.back().accessor["min"] = {skin.keyTimes.front()};
        parts.back().accessor["max"] = {skin.keyTimes.back()};
        for (const std::vector<Vec4>& rotations : skin.keyRotations)
            parts.push_back(part(rotations, "VEC4", kFloat));
    }
    for (const MorphTarget& target : mesh.morphTargets) parts.push_back(positionPart(target.positionDeltas));
    uint64_t offset = 0;
    for (BinPart& p : parts) {
        p.offset = offset;
        offset += p.bytes;
    }
    return parts;
}

uint64_t binBytes(const std::vector<BinPart>& parts) { return parts.back().offset + parts.back().bytes; }

// Accessor indices of binParts' parts.
enum : int { kPositions, kNormals, kIndices, kJoints, kWeights, kInverseBinds, kKeyTimes, kFirstRotations };

// The accessor of the first morph target's position deltas: after the skin's, if any.
size_t firstMorphAccessor(const GenScene& scene) {
    return scene.skin ? kFirstRotations + scene.skin->keyRotations.size() : size_t(kIndices) + 1;
}

// A URI reference for a file name: every byte outside RFC 3986's unreserved set escaped
// ("+" too, which tinygltf reads as a space).
std::string encodeUri(const std::string& name) {
    std::string out;
    for (unsigned char c : name) {
        if (std::isalnum(c) || c == '-' || c == '.' || c == '_' || c == '~') {
            out += char(c);
        } else {
            char escaped[4];
            std::snprintf(escaped, sizeof escaped, "%%%02X", c);
            out += escaped;
        }
    }
    return out;
}

struct FileCloser {
    void operator()(std::FILE* f) const { std::fclose(f); }
};
using File = std::unique_ptr<std::FILE, FileCloser>;

File openForWrite(const std::string& temp, const std::string& path) {
    File f(std::fopen(temp.c_str(), "wb"));
    if (!f) throw std::runtime_error(path + ": cannot write (" + std::strerror(errno) + ")");
    return f;
}

void closeChecked(File f, const std::string& path) {
    const bool failed = std::ferror(f.get()) != 0;
    if (std::fclose(f.release()) != 0 || failed) throw std::runtime_error(path + ": write failed");
}

void writeBin(const GenScene& scene, const std::string& path, const ProgressFn& progress) {
    const std::vector<BinPart> parts = binParts(scene);
    const uint64_t total = binBytes(parts);
    writeFileAtomically(path, [&](const std::string& temp) {
        File f = openForWrite(temp, path);
        constexpr uint64_t kChunk = 8u << 20;  // progress every 8 MiB
        uint64_t written = 0;
        for (const BinPart& part : parts) {
            const char* bytes = static_cast<const char*>(part.data);
            for (uint64_t at = 0; at < part.bytes; at += kChunk) {
                const size_t n = size_t(std::min(kChunk, part.bytes - at));
                if (std::fwrite(bytes + at, 1, n, f.get()) != n)
                    throw std::runtime_error(path + ": write failed");
                written += n;
                reportProgress(progress, "write bin", double(written) / double(std::max<uint64_t>(total, 1)));
            }
        }
        closeChecked(std::move(f), path);
    });
}

size_t firstJointNode(const GenScene& scene) { return 1 + scene.lights.size() + scene.instances.size(); }

// The skin over the joint nodes and its animation: a LINEAR rotation channel per joint from 1 on.
void addSkin(nlohmann::ordered_json& j, const GenScene& scene) {
    using nlohmann::ordered_json;
    const GenSkin& skin = *scene.skin;
    ordered_json joints = ordered_json::array();
    for (size_t k = 0; k < skin.joints.size(); ++k) joints.push_back(firstJointNode(scene) + k);
    j["skins"] = {{{"joints", joints}, {"inverseBindMatrices", int(kInverseBinds)}}};
    ordered_json samplers = ordered_json::array(), channels = ordered_json::array();
    for (size_t k = 0; k < skin.keyRotations.size(); ++k) {
        samplers.push_back(
            {{"input", int(kKeyTimes)}, {"output", kFirstRotations + k}, {"interpolation", "LINEAR"}});
        channels.push_back(
            {{"sampler", k}, {"target", {{"node", firstJointNode(scene) + 1 + k}, {"path", "rotation"}}}});
    }
    j["animations"] = {{{"name", skin.animation}, {"samplers", samplers}, {"channels", channels}}};
}

// The one mesh of one primitive. Morph targets carry POSITION deltas only; their names go in
// extras.targetNames, the convention Blender and three.js follow (glTF itself names none).
nlohmann::ordered_json meshJson(const GenScene& scene) {
    using nlohmann::ordered_json;
    const Mesh& mesh = scene.mesh;
    ordered_json attributes = {{"POSITION", int(kPositions)}, {"NORMAL", int(kNormals)}};
    if (scene.skin) {
        attributes["JOINTS_0"] = int(kJoints);
        attributes["WEIGHTS_0"] = int(kWeights);
    }
    ordered_json primitive = {{"attributes", attributes}, {"indices", int(kIndices)}, {"material", 0}};
    ordered_json targets = ordered_json::array(), names = ordered_json::array();
    for (size_t t = 0; t < mesh.morphTargets.size(); ++t) {
        targets.push_back({{"POSITION", firstMorphAccessor(scene) + t}});
        names.push_back(mesh.morphTargets[t].name);
    }
    if (!targets.empty()) primitive["targets"] = targets;
    ordered_json out = {{"name", mesh.name}, {"primitives", ordered_json::array({primitive})}};
    if (!targets.empty()) {
        out["weights"] = mesh.morphWeights;
        out["extras"] = {{"targetNames", names}};
    }
    return out;
}

// Everything but the nodes and the scene that lists them, which stream after it.
nlohmann::ordered_json documentHead(const GenScene& scene, const std::string& binUri) {
    using nlohmann::ordered_json;
    const std::vector<BinPart> parts = binParts(scene);
    ordered_json j;
    j["asset"] = {{"version", "2.0"}, {"generator", "pt-render gen"}};
    j["extensionsUsed"] = {"KHR_lights_punctual"};
    ordered_json lights = ordered_json::array();
    for (const GenLight& light : scene.lights) {
        lights.push_back({{"name", light.name},
                          {"type", "directional"},
                          {"color", {light.color[0], light.color[1], light.color[2]}},
                          {"intensity", light.intensity}});
    }
    j["extensions"] = {{"KHR_lights_punctual", {{"lights", lights}}}};
    j["scene"] = 0;
    j["buffers"] = {{{"uri", binUri}, {"byteLength", binBytes(parts)}}};
    ordered_json views = ordered_json::array(), accessors = ordered_json::array();
    for (size_t i = 0; i < parts.size(); ++i) {
        ordered_json view = {{"buffer", 0}, {"byteOffset", parts[i].offset}, {"byteLength", parts[i].bytes}};
        if (parts[i].target) view["target"] = parts[i].target;
        views.push_back(view);
        ordered_json accessor = {{"bufferView", i}};
        accessor.update(parts[i].accessor);
        accessors.push_back(accessor);
    }
    j["bufferViews"] = views;
    j["accessors"] = accessors;
    j["materials"] = {
        {{"name", "default"},
         {"pbrMetallicRoughness",
          {{"baseColorFactor", {0.8, 0.8, 0.8, 1.0}}, {"metallicFactor", 0.0}, {"roughnessFactor", 0.5}}}}};
    j["meshes"] = ordered_json::array({meshJson(scene)});
    j["cameras"] = {{{"name", "camera"},
                     {"type", "perspective"},
                     {"perspective", {{"yfov", scene.camera.yfovRadians}, {"znear", scene.camera.znear}}}}};
    if (scene.skin) addSkin(j, scene);
    return j;
}

// One node as compact JSON: `fields` (name, what it references), then its TRS, leaving out
// identity parts. Floats to 9 significant digits, which read back to the same float.
void writeNode(std::FILE* f, const GenNode& node, const std::string& fields) {
    std::fprintf(f, "    {%s", fields.c_str());
    const Vec3 t = node.translation;
    if (t != Vec3(0.0f)) std::fprintf(f, ", \"translation\": [%.9g, %.9g, %.9g]", t.x, t.y, t.z);
    const Vec4 q = node.rotation;
    if (q.x != 0.0f || q.y != 0.0f || q.z != 0.0f || q.w != 1.0f) {
        std::fprintf(f, ", \"rotation\": [%.9g, %.9g, %.9g, %.9g]", q.x, q.y, q.z, q.w);
    }
    if (node.scale != 1.0f)
        std::fprintf(f, ", \"scale\": [%.9g, %.9g, %.9g]", node.scale, node.scale, node.scale);
    std::fputs("}", f);
}

std::string nameField(const std::string& name) { return "\"name\": " + nlohmann::json(name).dump() + ", "; }

// Nodes: the camera, the lights, then one per instance; the scene lists them all.
void writeNodes(std::FILE* f, const GenScene& scene, const ProgressFn& progress) {
    std::fputs(",\n  \"nodes\": [\n", f);
    writeNode(f, scene.camera.node, nameField("camera") + "\"camera\": 0");
    for (size_t i = 0; i < scene.lights.size(); ++i) {
        std::fputs(",\n", f);
        writeNode(f, scene.lights[i].node,
                  nameField(scene.lights[i].name) +
                      "\"extensions\": {\"KHR_lights_punctual\": {\"light\": " + std::to_string(i) + "}}");
    }
    const std::string meshField = scene.skin ? "\"mesh\": 0, \"skin\": 0" : "\"mesh\": 0";
    for (size_t i = 0; i < scene.instances.size(); ++i) {
        std::fputs(",\n", f);
        writeNode(f, scene.instances[i], meshField);
        if (i % 65536 == 0)
            reportProgress(progress, "write glTF", double(i) / double(scene.instances.size()));
    }
    // A skin's joints: a chain, each the parent of the next; the first is a root.
    const size_t jointCount = scene.skin ? scene.skin->joints.size() : 0;
    for (size_t k = 0; k < jointCount; ++k) {
        std::fputs(",\n", f);
        const std::string children =
            k + 1 < jointCount ? ", \"children\": [" + std::to_string(firstJointNode(scene) + k + 1) + "]"
                               : "";
        writeNode(f, scene.skin->joints[k], "\"name\": \"joint " + std::to_string(k) + "\"" + children);
    }
    std::fputs("\n  ],\n  \"scenes\": [{\"nodes\": [", f);
    const size_t rootCount = firstJointNode(scene) + (jointCount > 0 ? 1 : 0);
    for (size_t i = 0; i < rootCount; ++i) std::fprintf(f, i == 0 ? "%zu" : ", %zu", i);
    std::fputs("]}]\n}\n", f);
    reportProgress(progress, "write glTF", 1.0);
}

void writeJson(const GenScene& scene, const std::string& path, const std::string& binUri,
               const ProgressFn& progress) {
    std::string head = documentHead(scene, binUri).dump(2);
    head.pop_back();  // the closing brace: nodes and scenes follow
    while (!head.empty() && head.back() == '\n') head.pop_back();
    writeFileAtomically(path, [&](const std::string& temp) {
        File f = openForWrite(temp, path);
        std::fputs(head.c_str(), f.get());
        writeNodes(f.get(), scene, progress);
        closeChecked(std::move(f), path);
    });
}

}  // namespace

std::string binPathFor(const std::string& gltfPath) {
    return std::filesystem::path(gltfPath).replace_extension(".bin").string();
}

void writeGenGltf(const GenScene& scene, const std::string& gltfPath, const ProgressFn& progress) {
    const std::string binPath = binPathFor(gltfPath);
    // The .bin first: a reader that sees the new .gltf finds the new buffer beside it.
    writeBin(scene, binPath, progress);
    writeJson(scene, gltfPath, encodeUri(std::filesystem::path(binPath).filename().string()), progress);
}

}  // namespace pt::cli
