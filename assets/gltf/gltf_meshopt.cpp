#include "assets/gltf/gltf_meshopt.h"

#if PT_HAVE_MESHOPT
#include <meshoptimizer.h>
#endif

namespace pt {

#if PT_HAVE_MESHOPT
namespace {

// Past this a decoded view is taken for a lie (the largest real ones hold tens of MB).
constexpr uint64_t kMaxDecodedBytes = uint64_t(1) << 31;

struct MeshoptView {
    int buffer = -1;
    uint64_t byteOffset = 0, byteLength = 0, byteStride = 0, count = 0;
    std::string mode, filter = "NONE";
};

uint64_t whole(const GltfContext& ctx, const tinygltf::Value& ext, const char* key, bool required,
               const std::string& element) {
    const tinygltf::Value& v = ext.Get(key);
    if (!v.IsNumber() && !v.IsInt()) {
        if (required) ctx.fail(element, std::string(key) + " is missing");
        return 0;
    }
    const double d = v.GetNumberAsDouble();
    if (!(d >= 0.0) || d > 9.0e15 || d != double(uint64_t(d))) {
        ctx.fail(element + "." + key, "expected a whole number, got " + std::to_string(d));
    }
    return uint64_t(d);
}

MeshoptView parse(const GltfContext& ctx, const tinygltf::Value& ext, const std::string& element) {
    MeshoptView m;
    m.buffer = int(whole(ctx, ext, "buffer", true, element));
    m.byteOffset = whole(ctx, ext, "byteOffset", false, element);
    m.byteLength = whole(ctx, ext, "byteLength", true, element);
    m.byteStride = whole(ctx, ext, "byteStride", true, element);
    m.count = whole(ctx, ext, "count", true, element);
    if (!ext.Get("mode").IsString()) ctx.fail(element, "mode is missing");
    m.mode = ext.Get("mode").Get<std::string>();
    if (ext.Get("filter").IsString()) m.filter = ext.Get("filter").Get<std::string>();
    const bool attributes = m.mode == "ATTRIBUTES";
    if (!attributes && m.mode != "TRIANGLES" && m.mode != "INDICES") {
        ctx.fail(element + ".mode", "'" + m.mode + "' is not ATTRIBUTES, TRIANGLES or INDICES");
    }
    if (attributes ? (m.byteStride == 0 || m.byteStride % 4 != 0 || m.byteStride > 256)
                   : (m.byteStride != 2 && m.byteStride != 4)) {
        ctx.fail(element + ".byteStride", std::to_string(m.byteStride) + " is not allowed in mode " + m.mode);
    }
    if (m.mode == "TRIANGLES" && m.count % 3 != 0) ctx.fail(element + ".count", "is not a multiple of 3");
    const bool filterFits =
        m.filter == "NONE" ||
        (attributes && m.filter == "OCTAHEDRAL" && (m.byteStride == 4 || m.byteStride == 8)) ||
        (attributes && m.filter == "QUATERNION" && m.byteStride == 8) ||
        (attributes && m.filter == "EXPONENTIAL");
    if (!filterFits) {
        ctx.fail(element + ".filter", "'" + m.filter + "' does not apply to mode " + m.mode +
                                          " with byteStride " + std::to_string(m.byteStride));
    }
    if (m.count > kMaxDecodedBytes / m.byteStride) {
        ctx.fail(element, std::to_string(m.count) + " elements of " + std::to_string(m.byteStride) +
                              " bytes: too large to decode");
    }
    return m;
}

std::vector<uint8_t> decode(const GltfContext& ctx, const MeshoptView& m, const std::string& element) {
    gltfElement(ctx, ctx.model().buffers, m.buffer, element + ".buffer", "buffer");
    const Span<const uint8_t> buffer = gltfBufferBytes(ctx.doc, m.buffer);
    if (m.byteOffset > buffer.count || m.byteLength > buffer.count - m.byteOffset) {
        ctx.fail(element, "bytes [" + std::to_string(m.byteOffset) + ", " +
                              std::to_string(m.byteOffset + m.byteLength) + ") run past the end of buffer " +
                              std::to_string(m.buffer) + " (" + std::to_string(buffer.count) + " bytes)");
    }
    const unsigned char* source = buffer.data + m.byteOffset;
    std::vector<uint8_t> out(size_t(m.count * m.byteStride));
    const size_t count = size_t(m.count), stride = size_t(m.byteStride), length = size_t(m.byteLength);
    const int status =
        m.mode == "ATTRIBUTES"  ? meshopt_decodeVertexBuffer(out.data(), count, stride, source, length)
        : m.mode == "TRIANGLES" ? meshopt_decodeIndexBuffer(out.data(), count, stride, source, length)
                                : meshopt_decodeIndexSequence(out.data(), count, stride, source, length);
    if (status != 0)
        ctx.fail(element, "the compressed data cannot be decoded (meshoptimizer error " +
                              std::to_string(status) + ")");
    if (m.filter == "OCTAHEDRAL") meshopt_decodeFilterOct(out.data(), count, stride);
    if (m.filter == "QUATERNION") meshopt_decodeFilterQuat(out.data(), count, stride);
    if (m.filter == "EXPONENTIAL") meshopt_decodeFilterExp(out.data(), count, stride);
    return out;
}

}  // namespace

bool gltfMeshoptAvailable() { return true; }

const std::vector<uint8_t>* meshoptView(const GltfContext& ctx, int view) {
    if (auto done = ctx.decodedViews.find(view); done != ctx.decodedViews.end()) return &done->second;
    if (view < 0 || size_t(view) >= ctx.model().bufferViews.size()) return nullptr;
    const auto& extensions = ctx.model().bufferViews[size_t(view)].extensions;
    const auto found = extensions.find(kMeshoptExtension);
    if (found == extensions.end()) return nullptr;
    const std::string element = gltfPath("bufferViews", size_t(view)) + ".extensions." + kMeshoptExtension;
    std::vector<uint8_t> bytes = decode(ctx, parse(ctx, found->second, element), element);
    return &(ctx.decodedViews[view] = std::move(bytes));
}

#else

bool gltfMeshoptAvailable() { return false; }

const std::vector<uint8_t>* meshoptView(const GltfContext&, int) { return nullptr; }

#endif

}  // namespace pt
