// pt_draco_fixture OUT.bin: encodes the tent (tent.h) with Draco's own encoder into OUT.bin and
// prints what a glTF around it must say: "<position id> <normal id> <uv id> <points> <faces>".
// A program of its own because libdraco must not join one that imports glTF
// (assets/draco_decoder.h).
#include <draco/compression/decode.h>
#include <draco/compression/encode.h>
#include <draco/mesh/triangle_soup_mesh_builder.h>

#include <cstdio>
#include <fstream>

#include "tent.h"

int main(int argc, char** argv) {
    if (argc != 2) {
        std::fprintf(stderr, "usage: pt_draco_fixture OUT.bin\n");
        return 2;
    }
    const std::vector<pt::test::TentCorner> corners = pt::test::tentCorners();
    draco::TriangleSoupMeshBuilder builder;
    const int faces = int(corners.size() / 3);
    builder.Start(faces);
    const int pos = builder.AddAttribute(draco::GeometryAttribute::POSITION, 3, draco::DT_FLOAT32);
    const int nor = builder.AddAttribute(draco::GeometryAttribute::NORMAL, 3, draco::DT_FLOAT32);
    const int tex = builder.AddAttribute(draco::GeometryAttribute::TEX_COORD, 2, draco::DT_FLOAT32);
    for (int f = 0; f < faces; ++f) {
        const pt::test::TentCorner* c = &corners[size_t(3 * f)];
        builder.SetAttributeValuesForFace(pos, draco::FaceIndex(f), c[0].p, c[1].p, c[2].p);
        builder.SetAttributeValuesForFace(nor, draco::FaceIndex(f), c[0].n, c[1].n, c[2].n);
        builder.SetAttributeValuesForFace(tex, draco::FaceIndex(f), c[0].uv, c[1].uv, c[2].uv);
    }
    const std::unique_ptr<draco::Mesh> mesh = builder.Finalize();
    draco::Encoder encoder;
    encoder.SetAttributeQuantization(draco::GeometryAttribute::POSITION, 14);
    encoder.SetAttributeQuantization(draco::GeometryAttribute::TEX_COORD, 12);
    encoder.SetAttributeQuantization(draco::GeometryAttribute::NORMAL, 10);
    draco::EncoderBuffer buffer;
    if (!encoder.EncodeMeshToBuffer(*mesh, &buffer).ok()) return 1;
    std::ofstream(argv[1], std::ios::binary).write(buffer.data(), std::streamsize(buffer.size()));
    // The accessors count the decoded mesh's points and corners (the encoder may merge points).
    draco::DecoderBuffer in;
    in.Init(buffer.data(), buffer.size());
    draco::Decoder decoder;
    auto decoded = decoder.DecodeMeshFromBuffer(&in);
    if (!decoded.ok()) return 1;
    std::printf("%u %u %u %u %u\n", mesh->attribute(pos)->unique_id(), mesh->attribute(nor)->unique_id(),
                mesh->attribute(tex)->unique_id(), decoded.value()->num_points(),
                decoded.value()->num_faces());
    return 0;
}
