#include "assets/gltf/gltf_glb_bin.h"

#include <string>

#include "assets/gltf/gltf_tinygltf_compat.h"

namespace pt {
namespace {

bool lacksUri(const nlohmann::json& buffer) { return buffer.is_object() && !buffer.contains("uri"); }

// An optional integer property as tinygltf's ParseIntegerProperty reads it: 0 where absent.
int integerOr0(const nlohmann::json& object, const char* name) {
    auto value = object.find(name);
    return value != object.end() && value->is_number_integer() ? value->get<int>() : 0;
}

}  // namespace

std::optional<DetachedGlbBin> detachGlbBin(nlohmann::json& root) {
    auto buffers = root.find("buffers");
    if (buffers == root.end() || !buffers->is_array() || buffers->empty() || !lacksUri((*buffers)[0])) {
        return std::nullopt;
    }
    for (size_t i = 1; i < buffers->size(); ++i) {
        if (lacksUri((*buffers)[i])) return std::nullopt;  // tinygltf's own path: left as it was
    }
    DetachedGlbBin detached;
    nlohmann::json& bin = (*buffers)[0];
    detached.byteLength = bin.at("byteLength").get<size_t>();
    standInForTinygltf(bin);
    auto images = root.find("images");
    if (images != root.end() && images->is_array()) {
        for (size_t i = 0; i < images->size(); ++i) {
            nlohmann::json& image = (*images)[i];
            // An image with a uri is tinygltf's to read (or, beside a view, to reject).
            if (!image.is_object() || image.contains("uri")) continue;
            auto view = image.find("bufferView");
            if (view == image.end() || !view->is_number_integer()) continue;
            auto mimeType = image.find("mimeType");
            detached.imageViews.push_back(
                {i, view->get<int>(), integerOr0(image, "width"), integerOr0(image, "height"),
                 mimeType != image.end() && mimeType->is_string() ? mimeType->get<std::string>() : ""});
            image.erase(view);
            image["uri"] = kTinygltfStandInUri;
        }
    }
    return detached;
}

void attachGlbBin(tinygltf::Model& model, const DetachedGlbBin& detached) {
    tinygltf::Buffer& buffer = model.buffers.at(0);
    buffer.data.clear();  // the stand-in's: the import reads the chunk (GltfDocument::mappedBuffers)
    buffer.uri.clear();
    for (const DetachedGlbBin::ImageView& view : detached.imageViews) {
        tinygltf::Image& image = model.images.at(view.image);
        image.bufferView = view.bufferView;
        image.width = view.width;
        image.height = view.height;
        image.mimeType = view.mimeType;
        image.uri.clear();
        image.image.clear();
        image.as_is = false;
    }
}

}  // namespace pt
