// The pt_draco module (draco_decoder.h): Draco's decoder behind a table of functions.
#include <draco/compression/decode.h>

#include "assets/gltf/draco_decoder.h"

namespace pt {
namespace {

DracoMesh decodeDraco(const uint8_t* bytes, size_t size) {
    DracoMesh out;
    draco::DecoderBuffer buffer;
    buffer.Init(reinterpret_cast<const char*>(bytes), size);
    draco::Decoder decoder;
    auto decoded = decoder.DecodeMeshFromBuffer(&buffer);
    if (!decoded.ok()) {
        out.error = decoded.status().error_msg_string();
        return out;
    }
    const std::unique_ptr<draco::Mesh> mesh = std::move(decoded).value();
    out.points = mesh->num_points();
    out.corners.reserve(size_t(mesh->num_faces()) * 3);
    for (draco::FaceIndex f(0); f < mesh->num_faces(); ++f) {
        for (const draco::PointIndex& corner : mesh->face(f)) out.corners.push_back(corner.value());
    }
    for (int a = 0; a < mesh->num_attributes(); ++a) {
        const draco::PointAttribute* attribute = mesh->attribute(a);
        DracoMesh::Attribute values{attribute->unique_id(), attribute->num_components(), {}};
        values.values.resize(size_t(out.points) * size_t(values.components));
        for (draco::PointIndex p(0); p < mesh->num_points(); ++p) {
            float* at = &values.values[size_t(p.value()) * size_t(values.components)];
            if (!attribute->ConvertValue<float>(attribute->mapped_index(p), int8_t(values.components), at)) {
                out.error = "attribute " + std::to_string(values.id) + ": point " +
                            std::to_string(p.value()) + " cannot be read";
                return out;
            }
        }
        out.attributes.push_back(std::move(values));
    }
    return out;
}

}  // namespace
}  // namespace pt

extern "C" const void* ptDracoDecoder() {
    static const pt::DracoDecoder table{pt::decodeDraco};
    return &table;
}
