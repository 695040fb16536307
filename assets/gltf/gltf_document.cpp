#include "assets/gltf/gltf_document.h"

#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <nlohmann/json.hpp>
#include <optional>
#include <sstream>
#include <vector>

#include "assets/file_state.h"
#include "assets/gltf/gltf_external_buffers.h"
#include "assets/gltf/gltf_glb_bin.h"
#include "assets/gltf/gltf_json_check.h"
#include "assets/gltf/gltf_tinygltf_compat.h"
#include "assets/scene_json/json_depth.h"
#include "render/util/large_array.h"

namespace pt {
namespace {

// tinygltf takes sizes as unsigned int; nothing larger can be handed to it.
constexpr uint64_t kMaxFileBytes = std::numeric_limits<uint32_t>::max();

std::vector<uint8_t> readWholeFile(const std::string& path, const std::string& label) {
    std::error_code error;
    const auto size = std::filesystem::file_size(path, error);
    if (error || !std::filesystem::is_regular_file(path, error)) {
        throw InputError(label + ": cannot open '" + path + "'");
    }
    if (size > kMaxFileBytes) throw InputError(label + ": file larger than 4 GiB");
    std::vector<uint8_t> bytes;
    reserveOnHugePages(bytes, size);
    bytes.resize(size);
    std::ifstream in(path, std::ios::binary);
    if (!in || !in.read(reinterpret_cast<char*>(bytes.data()), std::streamsize(size))) {
        throw InputError(label + ": cannot read '" + path + "'");
    }
    return bytes;
}

uint32_t readU32(const Span<const uint8_t>& bytes, size_t offset) {
    uint32_t v;  // GLB is little-endian, like every machine we build for
    std::memcpy(&v, bytes.data + offset, 4);
    return v;
}

// The JSON chunk and the size of the BIN chunk of a .glb, with every length checked against
// the file (tinygltf 2.7 reads the BIN chunk up to 8 bytes past a lying chunk length).
struct GlbChunks {
    std::string json;
    size_t binBytes = 0;
    size_t binChunk = 0;  // where the BIN chunk's header starts (0: no BIN chunk)
};

GlbChunks splitGlb(const Span<const uint8_t>& bytes, const std::string& label) {
    auto fail = [&](const std::string& what) { throw InputError(label + ": GLB " + what); };
    if (bytes.count < 20) fail("header: file too short");
    if (readU32(bytes, 4) != 2)
        fail("header: version " + std::to_string(readU32(bytes, 4)) + " is not supported (expected 2)");
    const uint64_t length = readU32(bytes, 8);
    if (length > bytes.count) {
        fail("header: length " + std::to_string(length) + " is past the end of the file (" +
             std::to_string(bytes.count) + " bytes)");
    }
    const uint64_t jsonLength = readU32(bytes, 12);
    if (readU32(bytes, 16) != 0x4E4F534Au) fail("chunk 0: not a JSON chunk");
    if (jsonLength == 0 || 20 + jsonLength > length) fail("chunk 0: length runs past the file");
    GlbChunks chunks;
    chunks.json.assign(reinterpret_cast<const char*>(bytes.data) + 20, size_t(jsonLength));
    const uint64_t binHeader = 20 + jsonLength;
    if (binHeader == length) return chunks;
    if (binHeader + 8 > length) fail("chunk 1: header runs past the file");
    const uint64_t binLength = readU32(bytes, size_t(binHeader));
    if (readU32(bytes, size_t(binHeader) + 4) != 0x004E4942u) fail("chunk 1: not a BIN chunk");
    if (binLength < 4 || binLength % 4 != 0) {
        fail("chunk 1: length " + std::to_string(binLength) + " is not a multiple of 4");
    }
    if (binHeader + 8 + binLength > length) fail("chunk 1: length runs past the file");
    chunks.binBytes = size_t(binLength);
    chunks.binChunk = size_t(binHeader);
    return chunks;
}

void appendU32(std::vector<uint8_t>& out, uint32_t v) {
    const uint8_t* p = reinterpret_cast<const uint8_t*>(&v);
    out.insert(out.end(), p, p + 4);
}

// The .glb with its JSON chunk replaced by `json` (padded with spaces to 4 bytes, as the
// spec asks) and its BIN chunk as it was.
std::vector<uint8_t> replaceGlbJson(const Span<const uint8_t>& bytes, const GlbChunks& chunks,
                                    std::string json) {
    while (json.size() % 4 != 0) json += ' ';
    const size_t binChunkBytes = chunks.binChunk ? 8 + chunks.binBytes : 0;
    std::vector<uint8_t> out;
    out.reserve(20 + json.size() + binChunkBytes);
    out.insert(out.end(), bytes.data, bytes.data + 8);  // magic, version
    appendU32(out, uint32_t(20 + json.size() + binChunkBytes));
    appendU32(out, uint32_t(json.size()));
    appendU32(out, 0x4E4F534Au);
    out.insert(out.end(), json.begin(), json.end());
    if (chunks.binChunk) {
        const uint8_t* bin = bytes.data + chunks.binChunk;
        out.insert(out.end(), bin, bin + binChunkBytes);
    }
    return out;
}

// tinygltf image callback: keeps encoded bytes (from a data URI or an external file) in
// image->image, marked as_is. Images in bufferViews are read later with bounds checks.
bool keepEncodedImage(tinygltf::Image* image, const int, std::string*, std::string*, int, int,
                      const unsigned char* bytes, int size, void*) {
    if (image->bufferView >= 0 || bytes == nullptr || size <= 0) return true;
    image->image.assign(bytes, bytes + size);
    image->as_is = true;
    return true;
}

// tinygltf's file reader, replaced (FsCallbacks::ReadWholeFile): its own opened a folder as a
// stream, took its size as -1 and died of std::bad_alloc. This one reads regular files of up
// to 4 GiB and otherwise says why not; tinygltf then warns (images) or fails (buffers).
bool readFileForTinygltf(std::vector<unsigned char>* out, std::string* err, const std::string& path, void*) {
    const FileState state = fileState(path);
    if (state != FileState::Readable && state != FileState::Empty) {
        if (err) *err += path + ": " + fileStateWords(state) + "\n";
        return false;
    }
    try {
        *out = readWholeFile(path, path);
    } catch (const InputError& e) {
        if (err) *err += std::string(e.what()) + "\n";
        return false;
    }
    return true;
}

// tinygltf's error text, one line per problem; data URIs can make lines very long.
std::string summarize(const std::string& text) {
    std::istringstream lines(text);
    std::string line, out;
    while (std::getline(lines, line)) {
        if (line.empty()) continue;
        if (line.size() > 240) line = line.substr(0, 240) + "...";
        out += (out.empty() ? "" : "; ") + line;
    }
    return out;
}

}  // namespace

GltfDocument loadGltfDocument(const std::string& path) {
    GltfDocument doc;
    doc.path = path;
    doc.label = std::filesystem::path(path).filename().string();
    const std::string parent = std::filesystem::path(path).parent_path().string();
    doc.baseDir = parent.empty() ? "." : parent;

    MappedFile mapped(path, doc.label);
    const Span<const uint8_t> bytes = mapped.bytes();
    const bool binary = bytes.count >= 4 && std::memcmp(bytes.data, "glTF", 4) == 0;
    std::optional<GlbChunks> glb;
    if (binary) glb = splitGlb(bytes, doc.label);
    std::string jsonText =
        binary ? glb->json : std::string(reinterpret_cast<const char*>(bytes.data), bytes.count);

    checkJsonDepth(jsonText, doc.label);  // before nlohmann and tinygltf recurse over it
    nlohmann::json root;
    try {
        root = nlohmann::json::parse(jsonText);
    } catch (const nlohmann::json::exception& e) {
        throw InputError(doc.label + ": invalid JSON: " + e.what());
    }
    checkGltfJson(root,
                  {doc.label, doc.baseDir, binary ? std::optional<size_t>(glb->binBytes) : std::nullopt});
    const bool adapted = adaptGltfForTinygltf(root);
    // A .glb's BIN chunk: tinygltf parses the JSON alone, and buffer 0 is the chunk where it
    // lies in the mapped file; a .gltf's buffer files are mapped likewise.
    const std::optional<DetachedGlbBin> detached =
        binary && glb->binChunk != 0 ? detachGlbBin(root) : std::nullopt;
    const std::vector<ExternalBufferFile> external = detachExternalBuffers(root, doc.baseDir);
    std::vector<uint8_t> rewrittenGlb;  // a .glb whose JSON changed and whose chunk tinygltf reads
    if (adapted || detached || !external.empty()) {
        jsonText = root.dump();
        if (binary && !detached) rewrittenGlb = replaceGlbJson(bytes, *glb, jsonText);
    }
    const Span<const uint8_t> glbForTinygltf =
        rewrittenGlb.empty() ? bytes
                             : Span<const uint8_t>{rewrittenGlb.data(), uint32_t(rewrittenGlb.size())};

    tinygltf::TinyGLTF loader;
    loader.SetImageLoader(&keepEncodedImage, nullptr);
    loader.SetFsCallbacks({&tinygltf::FileExists, &tinygltf::ExpandFilePath, &readFileForTinygltf,
                           &tinygltf::WriteWholeFile, nullptr});
    std::string err, warn;
    const bool ok = binary && !detached
                        ? loader.LoadBinaryFromMemory(&doc.model, &err, &warn, glbForTinygltf.data,
                                                      unsigned(glbForTinygltf.count), doc.baseDir)
                        : loader.LoadASCIIFromString(&doc.model, &err, &warn, jsonText.data(),
                                                     unsigned(jsonText.size()), doc.baseDir);
    // tinygltf appends some errors without failing; both are bad input. Its warnings are
    // only about external images, which the texture stage reports per image itself.
    if (!ok || !err.empty()) {
        throw InputError(doc.label + ": " + (err.empty() ? "tinygltf failed" : summarize(err)));
    }
    if (detached) {
        // Buffer 0 is the chunk where it lies in the mapped file (its length checked against
        // the chunk's).
        attachGlbBin(doc.model, *detached);
        doc.mappedBuffers[0] = {bytes.data + glb->binChunk + 8, uint32_t(detached->byteLength)};
        doc.mappedFiles.push_back(std::move(mapped));
    }
    for (const ExternalBufferFile& file : external) {
        doc.mappedFiles.emplace_back(file.path, doc.label);  // a move keeps the mapping where it is
        doc.mappedBuffers[file.buffer] = doc.mappedFiles.back().bytes();
    }
    return doc;
}

}  // namespace pt
