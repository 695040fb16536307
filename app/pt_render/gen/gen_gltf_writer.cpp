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

constexpr int kFloat = 5126, kUnsignedInt = 5125;
constexpr int kArrayBuffer = 34962, kElementArrayBuffer = 34963;

// The buffer: positions, normals, then indices, each tightly packed (all 4-byte aligned).
struct BufferLayout {
    uint64_t positions = 0, normals = 0, indices = 0, total = 0;

    explicit BufferLayout(const Mesh& mesh) {
        normals = positions + mesh.positions.size() * sizeof(Vec3);
        indices = normals + mesh.normals.size() * sizeof(Vec3);
        total = indices + mesh.indices.size() * sizeof(uint32_t);
    }
};

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

void writeBin(const Mesh& mesh, const std::string& path, const ProgressFn& progress) {
    const BufferLayout layout(mesh);
    const struct {
        const void* data;
        uint64_t bytes;
    } parts[] = {{mesh.positions.data(), layout.normals - layout.positions},
                 {mesh.normals.data(), layout.indices - layout.normals},
                 {mesh.indices.data(), layout.total - layout.indices}};
    writeFileAtomically(path, [&](const std::string& temp) {
        File f = openForWrite(temp, path);
        constexpr uint64_t kChunk = 8u << 20;  // progress every 8 MiB
        uint64_t written = 0;
        for (const auto& part : parts) {
            const char* bytes = static_cast<const char*>(part.data);
            for (uint64_t at = 0; at < part.bytes; at += kChunk) {
                const size_t n = size_t(std::min(kChunk, part.bytes - at));
                if (std::fwrite(bytes + at, 1, n, f.get()) != n)
                    throw std::runtime_error(path + ": write failed");
                written += n;
                reportProgress(progress, "write bin",
                               double(written) / double(std::max<uint64_t>(layout.total, 1)));
            }
        }
        closeChecked(std::move(f), path);
    });
}

void bounds(const std::vector<Vec3>& points, Vec3& lo, Vec3& hi) {
    lo = hi = points.empty() ? Vec3(0.0f) : points[0];
    for (const Vec3& p : points) {
        lo = vmin(lo, p);
        hi = vmax(hi, p);
    }
}

// Everything but the nodes and the scene that lists them, which stream after it.
nlohmann::ordered_json documentHead(const GenScene& scene, const std::string& binUri) {
    using nlohmann::ordered_json;
    const Mesh& mesh = scene.mesh;
    const BufferLayout layout(mesh);
    Vec3 lo, hi;
    bounds(mesh.positions, lo, hi);
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
    j["buffers"] = {{{"uri", binUri}, {"byteLength", layout.total}}};
    j["bufferViews"] = {{{"buffer", 0},
                         {"byteOffset", layout.positions},
                         {"byteLength", layout.normals - layout.positions},
                         {"target", kArrayBuffer}},
                        {{"buffer", 0},
                         {"byteOffset", layout.normals},
                         {"byteLength", layout.indices - layout.normals},
                         {"target", kArrayBuffer}},
                        {{"buffer", 0},
                         {"byteOffset", layout.indices},
                         {"byteLength", layout.total - layout.indices},
                         {"target", kElementArrayBuffer}}};
    j["accessors"] = {
        {{"bufferView", 0},
         {"componentType", kFloat},
         {"count", mesh.positions.size()},
         {"type", "VEC3"},
         {"min", {lo.x, lo.y, lo.z}},
         {"max", {hi.x, hi.y, hi.z}}},
        {{"bufferView", 1}, {"componentType", kFloat}, {"count", mesh.normals.size()}, {"type", "VEC3"}},
        {{"bufferView", 2},
         {"componentType", kUnsignedInt},
         {"count", mesh.indices.size()},
         {"type", "SCALAR"}}};
    j["materials"] = {
        {{"name", "default"},
         {"pbrMetallicRoughness",
          {{"baseColorFactor", {0.8, 0.8, 0.8, 1.0}}, {"metallicFactor", 0.0}, {"roughnessFactor", 0.5}}}}};
    j["meshes"] = {{{"name", mesh.name},
                    {"primitives",
                     {{{"attributes", {{"POSITION", 0}, {"NORMAL", 1}}}, {"indices", 2}, {"material", 0}}}}}};
    j["cameras"] = {{{"name", "camera"},
                     {"type", "perspective"},
                     {"perspective", {{"yfov", scene.camera.yfovRadians}, {"znear", scene.camera.znear}}}}};
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
    const std::string meshField = "\"mesh\": 0";
    for (size_t i = 0; i < scene.instances.size(); ++i) {
        std::fputs(",\n", f);
        writeNode(f, scene.instances[i], meshField);
        if (i % 65536 == 0)
            reportProgress(progress, "write glTF", double(i) / double(scene.instances.size()));
    }
    std::fputs("\n  ],\n  \"scenes\": [{\"nodes\": [", f);
    const size_t nodeCount = 1 + scene.lights.size() + scene.instances.size();
    for (size_t i = 0; i < nodeCount; ++i) std::fprintf(f, i == 0 ? "%zu" : ", %zu", i);
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
    writeBin(scene.mesh, binPath, progress);
    writeJson(scene, gltfPath, encodeUri(std::filesystem::path(binPath).filename().string()), progress);
}

}  // namespace pt::cli
