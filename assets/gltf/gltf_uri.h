#pragma once
// glTF URIs of external files are URL-encoded ("my%20texture.png"). This decodes them the
// way tinygltf 2.7 does ('+' is a space, "%xx" a byte), so that the file our checks look at is
// the file tinygltf opens. Internal to pt_assets.
#include <string>

namespace pt {

inline std::string decodeGltfUri(const std::string& uri) {
    auto hex = [](char c) -> int {
        if (c >= '0' && c <= '9') return c - '0';
        if (c >= 'a' && c <= 'f') return c - 'a' + 10;
        if (c >= 'A' && c <= 'F') return c - 'A' + 10;
        return -1;
    };
    std::string out;
    for (size_t i = 0; i < uri.size(); ++i) {
        if (uri[i] == '+') {
            out += ' ';
        } else if (uri[i] == '%' && i + 2 < uri.size() && hex(uri[i + 1]) >= 0 && hex(uri[i + 2]) >= 0) {
            out += char(hex(uri[i + 1]) * 16 + hex(uri[i + 2]));
            i += 2;
        } else {
            out += uri[i];
        }
    }
    return out;
}

}  // namespace pt
