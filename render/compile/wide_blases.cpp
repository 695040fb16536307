#include "render/compile/wide_blases.h"

#include <tbb/parallel_for.h>

#include "render/bvh/compressed_wide_bvh.h"
#include "render/bvh/wide_bvh.h"
#include "render/util/check.h"

namespace pt {

namespace {

// Nodes [first, end) of BLAS `blas` in a wide form whose BLASes start at `roots` (in order) and
// which holds `total` nodes.
std::pair<uint32_t, uint32_t> nodeRange(const std::vector<uint32_t>& roots, size_t total, uint32_t blas) {
    PT_CHECK(blas < roots.size());
    return {roots[blas], blas + 1 < roots.size() ? roots[blas + 1] : uint32_t(total)};
}

}  // namespace

void buildWideBlases(CompiledScene& compiled) {
    const size_t count = compiled.blases.size();
    std::vector<WideBvh> wide(count);
    tbb::parallel_for(size_t(0), count, [&](size_t i) {
        const BlasRef& blas = compiled.blases[i];
        wide[i] = collapseToWide(compiled.blasNodes.data() + blas.nodeOffset, blas.nodeCount);
    });
    compiled.blasWideNodes.clear();
    compiled.wideSourceNodes.clear();
    compiled.blasWideRoots.assign(count, 0);
    for (size_t i = 0; i < count; ++i) {
        const uint32_t first = uint32_t(compiled.blasWideNodes.size());
        compiled.blasWideRoots[i] = first;
        // Child indices were made relative to the BLAS's first wide node: made absolute here.
        for (WideBvhNode& node : wide[i].nodes) {
            for (uint32_t s = 0; s < WideBvhNode::kWidth; ++s) {
                if (node.count[s] == 0) node.child[s] += first;
            }
        }
        compiled.blasWideNodes.insert(compiled.blasWideNodes.end(), wide[i].nodes.begin(),
                                      wide[i].nodes.end());
        compiled.wideSourceNodes.insert(compiled.wideSourceNodes.end(), wide[i].sourceNodes.begin(),
                                        wide[i].sourceNodes.end());
    }
}

void buildCompressedBlases(CompiledScene& compiled) {
    const size_t count = compiled.blases.size();
    std::vector<CompressedWideBvh> wide(count);
    tbb::parallel_for(size_t(0), count, [&](size_t i) {
        const BlasRef& blas = compiled.blases[i];
        wide[i] = compressToWide(compiled.blasNodes.data() + blas.nodeOffset, blas.nodeCount,
                                 compiled.blasPrimIndices.data() + blas.primIndexOffset);
    });
    compiled.blasCompressedNodes.clear();
    compiled.blasCompressedPrims.clear();
    compiled.compressedSourceNodes.clear();
    compiled.blasCompressedRoots.assign(count, 0);
    for (size_t i = 0; i < count; ++i) {
        const uint32_t firstNode = uint32_t(compiled.blasCompressedNodes.size());
        const uint32_t firstPrim = uint32_t(compiled.blasCompressedPrims.size());
        compiled.blasCompressedRoots[i] = firstNode;
        for (CompressedWideNode& node : wide[i].nodes) {
            node.childBase += firstNode;
            node.primBase += firstPrim;
        }
        compiled.blasCompressedNodes.insert(compiled.blasCompressedNodes.end(), wide[i].nodes.begin(),
                                            wide[i].nodes.end());
        compiled.blasCompressedPrims.insert(compiled.blasCompressedPrims.end(), wide[i].primIndices.begin(),
                                            wide[i].primIndices.end());
        compiled.compressedSourceNodes.insert(compiled.compressedSourceNodes.end(),
                                              wide[i].sourceNodes.begin(), wide[i].sourceNodes.end());
    }
}

std::pair<uint32_t, uint32_t> compressedNodeRange(const CompiledScene& compiled, uint32_t blas) {
    return nodeRange(compiled.blasCompressedRoots, compiled.blasCompressedNodes.size(), blas);
}

void refreshWideBlas(CompiledScene& compiled, uint32_t blas) {
    const BvhNode* binary = compiled.blasNodes.data() + compiled.blases[blas].nodeOffset;
    if (!compiled.blasCompressedRoots.empty()) {
        const auto [first, end] = compressedNodeRange(compiled, blas);
        requantizeWideBoxes(
            binary, compiled.compressedSourceNodes.data() + size_t(first) * CompressedWideNode::kWidth,
            compiled.blasCompressedNodes.data() + first, end - first);
    }
    if (compiled.blasWideRoots.empty()) return;
    const auto [first, end] = nodeRange(compiled.blasWideRoots, compiled.blasWideNodes.size(), blas);
    refreshWideBoxes(binary, compiled.wideSourceNodes.data() + size_t(first) * WideBvhNode::kWidth,
                     compiled.blasWideNodes.data() + first, end - first);
}

}  // namespace pt
