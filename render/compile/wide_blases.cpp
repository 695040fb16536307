#include "render/compile/wide_blases.h"

#include <tbb/parallel_for.h>

#include "render/bvh/wide_bvh.h"
#include "render/util/check.h"

namespace pt {

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

void refreshWideBlas(CompiledScene& compiled, uint32_t blas) {
    if (compiled.blasWideRoots.empty()) return;
    PT_CHECK(blas < compiled.blasWideRoots.size());
    const uint32_t first = compiled.blasWideRoots[blas];
    const uint32_t end = blas + 1 < compiled.blasWideRoots.size() ? compiled.blasWideRoots[blas + 1]
                                                                  : uint32_t(compiled.blasWideNodes.size());
    refreshWideBoxes(compiled.blasNodes.data() + compiled.blases[blas].nodeOffset,
                     compiled.wideSourceNodes.data() + size_t(first) * WideBvhNode::kWidth,
                     compiled.blasWideNodes.data() + first, end - first);
}

}  // namespace pt
