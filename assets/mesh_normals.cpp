#include "assets/mesh_normals.h"

namespace pt {

void generateAreaWeightedNormals(const std::vector<Vec3>& positions, const std::vector<uint32_t>& indices,
                                 const std::vector<bool>& regenerate, std::vector<Vec3>& normals,
                                 const std::vector<uint32_t>* groups) {
    auto group = [groups](uint32_t v) { return groups ? (*groups)[v] : v; };
    std::vector<Vec3> sums(positions.size(), Vec3(0.0f));
    for (size_t t = 0; t + 2 < indices.size(); t += 3) {
        const uint32_t* tri = &indices[t];
        // Twice the triangle's area, along its geometric normal (counter-clockwise front).
        const Vec3 weighted =
            cross(positions[tri[1]] - positions[tri[0]], positions[tri[2]] - positions[tri[0]]);
        for (int k = 0; k < 3; ++k) {
            if (regenerate[tri[k]]) sums[group(tri[k])] += weighted;
        }
    }
    for (uint32_t v = 0; v < uint32_t(normals.size()); ++v) {
        if (!regenerate[v]) continue;
        const Vec3 sum = sums[group(v)];
        const float len = length(sum);
        normals[v] = len > 0.0f && std::isfinite(len) ? sum / len : Vec3(0.0f, 0.0f, 1.0f);
    }
}

}  // namespace pt
