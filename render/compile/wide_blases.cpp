#include "render/compile/wide_blases.h"

#include <tbb/parallel_for.h>

#include <stdexcept>
#include <string>

#include "render/bvh/compressed_wide_bvh.h"
#include "render/bvh/gather_leaf_triangles.h"
#include "render/bvh/wide_bvh.h"
#include "render/util/check.h"

namespace pt {

namespace {

// Nodes [first, end) of BLAS `blas` in a wide form whose BLASes start at `roots` (in order) and
// which holds `total` nodes (or the same of its triangle blocks).
std::pair<uint32_t, uint32_t> nodeRange(const std::vector<uint32_t>& roots, size_t total, uint32_t blas) {
    PT_CHECK(blas < roots.size());
    return {roots[blas], blas + 1 < roots.size() ? roots[blas + 1] : uint32_t(total)};
}

// Entries [first, end) of BLAS `blas` in compressed forms whose BLASes start at `roots` (in
// order) and which hold `total` entries. A BLAS's root is its first node filled, so its
// primBase is the BLAS's first entry.
std::pair<uint32_t, uint32_t> primRangeOf(const std::vector<CompressedWideNode>& nodes,
                                          const std::vector<uint32_t>& roots, size_t total, uint32_t blas) {
    const auto primBaseOf = [&](uint32_t b) {
        PT_CHECK(roots[b] < nodes.size());
        return nodes[roots[b]].primBase;
    };
    PT_CHECK(blas < roots.size());
    return {primBaseOf(blas), blas + 1 < roots.size() ? primBaseOf(blas + 1) : uint32_t(total)};
}

// The most triangles one wide leaf of a triangle BLAS gathers from a binary subtree: two
// blocks. A block tests four for about the price of one, and the boxes of small subtrees cull
// less than they cost to test. Measured with the 8-wide AVX2 walk on a 1M-triangle sphere
// (bench at 640x480, 2 threads), primary, diffuse and shadow Mrays/s, by this limit: 2: 10.2,
// 5.8, 5.0; 4: 12.7-12.9, 7.5-7.6, 6.5-6.6; 8: 15.0-15.1, 8.6-8.7, 7.3; 12: 14.7-15.0,
// 8.2-8.4, 7.1-7.2; 16: 15.0, 8.4, 7.1. Since AVX2 tests eight a pass (triangle_lanes.inl), a
// limit of 12 was 1-3% slower than 8 on each kind on one thread (medians of three alternated
// runs), so 8 stays.
constexpr uint32_t kLeafTriangles = 2 * TriangleBlock::kWidth;

// Lane `lane` of `block`: the corners of mesh-local triangle `local` of `blas`.
void setBlockLane(const CompiledScene& compiled, const BlasRef& blas, uint32_t local, TriangleBlock& block,
                  uint32_t lane) {
    const TriangleIndices tri = compiled.triangles[blas.primitiveOffset + local];
    const uint32_t corners[3] = {tri.v0, tri.v1, tri.v2};
    for (int c = 0; c < 3; ++c) {
        const Vec3 p = compiled.positions[corners[c]];
        for (int axis = 0; axis < 3; ++axis) block.corner[c][axis][lane] = p[axis];
    }
    block.primitive[lane] = local;
}

// The blocks of each leaf of the wide tree of triangle BLAS `blas`, one per four triangles
// (one or two, but for leaves the collapse did not make, as a deferred mesh's stand-in),
// consecutive;
// each leaf slot's child becomes its first block's index (from the BLAS's first block). Lanes
// past a leaf's count repeat its last block's first triangle (triangle_block.h).
std::vector<TriangleBlock> makeTriangleBlocks(const CompiledScene& compiled, const BlasRef& blas,
                                              WideBvh& wide) {
    std::vector<TriangleBlock> blocks;
    for (WideBvhNode& node : wide.nodes) {
        for (uint32_t s = 0; s < WideBvhNode::kWidth; ++s) {
            const uint32_t count = node.count[s];
            if (count == 0 || count == WideBvhNode::kEmpty) continue;
            const uint32_t firstBlock = uint32_t(blocks.size());
            for (uint32_t first = 0; first < count; first += TriangleBlock::kWidth) {
                TriangleBlock block;
                for (uint32_t lane = 0; lane < TriangleBlock::kWidth; ++lane) {
                    const uint32_t entry = node.child[s] + first + (first + lane < count ? lane : 0);
                    setBlockLane(compiled, blas, compiled.blasPrimIndices[blas.primIndexOffset + entry],
                                 block, lane);
                }
                blocks.push_back(block);
            }
            node.child[s] = firstBlock;
        }
    }
    return blocks;
}

// BLAS `blas`'s compressed leaf triangles, from its entries and the current positions.
void gatherCompressedTriangles(CompiledScene& compiled, uint32_t blas) {
    const auto [first, end] = compressedPrimRange(compiled, blas);
    tbb::parallel_for(first, end, [&](uint32_t i) {
        compiled.blasCompressedTriangles[i] =
            gatherLeafTriangle(compiled.triangles.data(), compiled.positions.data(), compiled.blases[blas],
                               compiled.blasCompressedPrims[i]);
    });
}

}  // namespace

void buildWideBlases(CompiledScene& compiled) {
    const size_t count = compiled.blases.size();
    std::vector<WideBvh> wide(count);
    std::vector<std::vector<TriangleBlock>> blocks(count);
    tbb::parallel_for(size_t(0), count, [&](size_t i) {
        const BlasRef& blas = compiled.blases[i];
        // Triangles: subtrees of up to kLeafTriangles become one leaf, tested a block of four
        // at a time. Spheres keep the binary leaves, tested one by one.
        const bool triangles = blas.kind == GeometryKind::Triangles;
        wide[i] = collapseToWide(compiled.blasNodes.data() + blas.nodeOffset, blas.nodeCount,
                                 triangles ? kLeafTriangles : 0);
        if (triangles) blocks[i] = makeTriangleBlocks(compiled, blas, wide[i]);
    });
    compiled.blasWideNodes.clear();
    compiled.wideSourceNodes.clear();
    compiled.blasTriangleBlocks.clear();
    compiled.blasWideRoots.assign(count, 0);
    compiled.blasFirstTriangleBlock.assign(count, 0);
    for (size_t i = 0; i < count; ++i) {
        const uint32_t first = uint32_t(compiled.blasWideNodes.size());
        const uint32_t firstBlock = uint32_t(compiled.blasTriangleBlocks.size());
        compiled.blasWideRoots[i] = first;
        compiled.blasFirstTriangleBlock[i] = firstBlock;
        // Child indices were made relative to the BLAS's first wide node, and block indices to
        // its first block: made absolute here.
        const bool blockLeaves = compiled.blases[i].kind == GeometryKind::Triangles;
        for (WideBvhNode& node : wide[i].nodes) {
            for (uint32_t s = 0; s < WideBvhNode::kWidth; ++s) {
                if (node.count[s] == 0)
                    node.child[s] += first;
                else if (blockLeaves && node.count[s] != WideBvhNode::kEmpty)
                    node.child[s] += firstBlock;
            }
        }
        compiled.blasWideNodes.insert(compiled.blasWideNodes.end(), wide[i].nodes.begin(),
                                      wide[i].nodes.end());
        compiled.wideSourceNodes.insert(compiled.wideSourceNodes.end(), wide[i].sourceNodes.begin(),
                                        wide[i].sourceNodes.end());
        compiled.blasTriangleBlocks.insert(compiled.blasTriangleBlocks.end(), blocks[i].begin(),
                                           blocks[i].end());
    }
}

CompressedBlases compressBlases(const CompiledScene& compiled, const std::vector<uint8_t>& skip) {
    const size_t count = compiled.blases.size();
    PT_CHECK(skip.size() == count);
    std::vector<CompressedWideBvh> wide(count);
    tbb::parallel_for(size_t(0), count, [&](size_t i) {
        const BlasRef& blas = compiled.blases[i];
        wide[i] = skip[i] ? compressToWide(nullptr, 0, nullptr)
                          : compressToWide(compiled.blasNodes.data() + blas.nodeOffset, blas.nodeCount,
                                           compiled.blasPrimIndices.data() + blas.primIndexOffset);
    });
    size_t entries = 0;
    for (const CompressedWideBvh& w : wide) entries += w.primIndices.size();
    if (entries >= kCompressedPrimitiveLimit) {
        throw std::invalid_argument("gpu_wide_bvh refused: the scene's BLASes hold " +
                                    std::to_string(entries) +
                                    " primitives, the compressed BVH at most 2^31 - 1");
    }
    CompressedBlases out;
    out.roots.assign(count, 0);
    for (size_t i = 0; i < count; ++i) {
        const uint32_t firstNode = uint32_t(out.forms.nodes.size());
        out.roots[i] = firstNode;
        rebaseCompressedNodes(wide[i], firstNode, uint32_t(out.forms.primIndices.size()));
        out.forms.nodes.insert(out.forms.nodes.end(), wide[i].nodes.begin(), wide[i].nodes.end());
        out.forms.primIndices.insert(out.forms.primIndices.end(), wide[i].primIndices.begin(),
                                     wide[i].primIndices.end());
        out.forms.sourceNodes.insert(out.forms.sourceNodes.end(), wide[i].sourceNodes.begin(),
                                     wide[i].sourceNodes.end());
    }
    return out;
}

std::pair<uint32_t, uint32_t> CompressedBlases::nodeRange(uint32_t blas) const {
    return pt::nodeRange(roots, forms.nodes.size(), blas);
}

std::pair<uint32_t, uint32_t> CompressedBlases::primRange(uint32_t blas) const {
    return primRangeOf(forms.nodes, roots, forms.primIndices.size(), blas);
}

void buildCompressedBlases(CompiledScene& compiled) {
    std::vector<uint8_t> deferred(compiled.blases.size(), 0);
    for (const DeferredBlas& d : compiled.deferredBlases) deferred[d.blas] = 1;
    CompressedBlases built = compressBlases(compiled, deferred);
    compiled.blasCompressedNodes = std::move(built.forms.nodes);
    compiled.blasCompressedPrims = std::move(built.forms.primIndices);
    compiled.compressedSourceNodes = std::move(built.forms.sourceNodes);
    compiled.blasCompressedRoots = std::move(built.roots);
    compiled.blasCompressedTriangles.resize(compiled.blasCompressedPrims.size());
    for (uint32_t i = 0; i < compiled.blases.size(); ++i) gatherCompressedTriangles(compiled, i);
}

std::pair<uint32_t, uint32_t> compressedNodeRange(const CompiledScene& compiled, uint32_t blas) {
    return nodeRange(compiled.blasCompressedRoots, compiled.blasCompressedNodes.size(), blas);
}

std::pair<uint32_t, uint32_t> compressedPrimRange(const CompiledScene& compiled, uint32_t blas) {
    return primRangeOf(compiled.blasCompressedNodes, compiled.blasCompressedRoots,
                       compiled.blasCompressedPrims.size(), blas);
}

void refreshWideBlas(CompiledScene& compiled, uint32_t blas) {
    const BvhNode* binary = compiled.blasNodes.data() + compiled.blases[blas].nodeOffset;
    if (!compiled.blasCompressedRoots.empty()) {
        const auto [first, end] = compressedNodeRange(compiled, blas);
        requantizeWideBoxes(
            binary, compiled.compressedSourceNodes.data() + size_t(first) * CompressedWideNode::kWidth,
            compiled.blasCompressedNodes.data() + first, end - first);
        gatherCompressedTriangles(compiled, blas);
    }
    if (compiled.blasWideRoots.empty()) return;
    const auto [first, end] = nodeRange(compiled.blasWideRoots, compiled.blasWideNodes.size(), blas);
    refreshWideBoxes(binary, compiled.wideSourceNodes.data() + size_t(first) * WideBvhNode::kWidth,
                     compiled.blasWideNodes.data() + first, end - first);
    // The blocks' copies of the moved corners.
    const auto [firstBlock, endBlock] =
        nodeRange(compiled.blasFirstTriangleBlock, compiled.blasTriangleBlocks.size(), blas);
    const BlasRef& ref = compiled.blases[blas];
    tbb::parallel_for(firstBlock, endBlock, [&](uint32_t b) {
        TriangleBlock& block = compiled.blasTriangleBlocks[b];
        for (uint32_t lane = 0; lane < TriangleBlock::kWidth; ++lane) {
            setBlockLane(compiled, ref, block.primitive[lane], block, lane);
        }
    });
}

}  // namespace pt
