#pragma once
// The Draco test's mesh, known to the fixture program that encodes it and to the test that
// imports it: a tent of four triangles over the unit square, apex (0.5, 0.5, 0.4), its normals
// up and its UVs the xy of each corner.
#include <vector>

namespace pt::test {

struct TentCorner {
    float p[3], n[3], uv[2];
};

inline std::vector<TentCorner> tentCorners() {
    const float square[4][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
    std::vector<TentCorner> corners;
    for (int side = 0; side < 4; ++side) {
        const float* a = square[side];
        const float* b = square[(side + 1) % 4];
        corners.push_back({{a[0], a[1], 0}, {0, 0, 1}, {a[0], a[1]}});
        corners.push_back({{b[0], b[1], 0}, {0, 0, 1}, {b[0], b[1]}});
        corners.push_back({{0.5f, 0.5f, 0.4f}, {0, 0, 1}, {0.5f, 0.5f}});
    }
    return corners;
}

}  // namespace pt::test
