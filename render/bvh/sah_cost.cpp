#include "render/bvh/sah_cost.h"

namespace pt {

namespace {

float nodeArea(const BvhNode& node) {
    Aabb box;
    box.lo = node.lo;
    box.hi = node.hi;
    return box.surfaceArea();
}

}  // namespace

float sahCost(const Bvh& bvh, const BvhBuildOptions& options) {
    if (bvh.primIndices.empty()) return 0.0f;
    return sahCost(bvh.nodes.data(), uint32_t(bvh.nodes.size()), options);
}

float sahCost(const BvhNode* nodes, uint32_t count, const BvhBuildOptions& options) {
    if (count == 0) return 0.0f;
    const double rootArea = nodeArea(nodes[0]);
    double sum = 0.0;  // double: a million leaves' terms would lose digits in float
    for (uint32_t i = 0; i < count; ++i) {
        const BvhNode& node = nodes[i];
        const double area = rootArea > 0.0 ? nodeArea(node) : 1.0;
        sum += node.isLeaf() ? double(options.intersectionCost) * node.count * area
                             : double(options.traversalCost) * area;
    }
    return float(rootArea > 0.0 ? sum / rootArea : sum);
}

}  // namespace pt
