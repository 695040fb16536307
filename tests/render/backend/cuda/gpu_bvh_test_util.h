#pragma once
// Shared by the device BVH tests (gpu_bvh_test.cpp): running gpu_bvh.h's functions on host
// input and downloading the results, the exact boxes a tree must hold, and a one-instance
// host scene over any downloaded BLAS for the shared traversal.
#include <cuda_runtime.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cstring>
#include <vector>

#include "render/backend/cuda/gpu_bvh.h"
#include "render/bvh/binned_sah_builder.h"
#include "render/bvh/bvh_test_util.h"
#include "render/bvh/instance_bounds.h"

namespace pt::test {

// A stream of its own, so the functions under test are not only tried on the legacy default
// stream, which would hide a missing stream argument.
struct TestStream {
    cudaStream_t stream = nullptr;
    TestStream() { PT_CUDA_CHECK(cudaStreamCreateWithFlags(&stream, cudaStreamNonBlocking)); }
    ~TestStream() { cudaStreamDestroy(stream); }
    void sync() const { PT_CUDA_CHECK(cudaStreamSynchronize(stream)); }
};

inline bool sameBits(const Aabb& a, const Aabb& b) { return std::memcmp(&a, &b, sizeof(Aabb)) == 0; }
inline bool sameBox(const BvhNode& node, const Aabb& box) { return node.lo == box.lo && node.hi == box.hi; }
inline Aabb boxOf(const BvhNode& node) {
    Aabb box;
    box.lo = node.lo;
    box.hi = node.hi;
    return box;
}

// A tree of `boxes` built on the device with `builder` (cuda::LbvhBuilder or cuda::PlocBuilder),
// downloaded.
template <class Builder>
Bvh buildTreeOnDevice(Builder& builder, const std::vector<Aabb>& boxes, const TestStream& s) {
    const uint32_t n = uint32_t(boxes.size());
    cuda::DeviceBuffer<Aabb> deviceBoxes;
    deviceBoxes.upload(boxes, s.stream);
    cuda::DeviceBuffer<BvhNode> nodes(cuda::lbvhNodeCount(n));
    cuda::DeviceBuffer<uint32_t> primIndices(n);
    builder.build(deviceBoxes.data(), n, nodes.data(), primIndices.data(), s.stream);
    s.sync();
    Bvh bvh;
    nodes.download(bvh.nodes);
    primIndices.download(bvh.primIndices);
    return bvh;
}

// BvhLeafCollapse's result worked out on the host, one node after another, from the choices of
// render/bvh/subtree_collapse.h: kept nodes (those no chosen leaf lies above) in their order,
// each kept pair at the next free pair of slots, each leaf's primitives (left to right) after
// the previous kept leaf's. The device's result must equal it bit for bit.
inline Bvh collapseOnHost(const Bvh& tree) {
    const uint32_t count = uint32_t(tree.nodes.size());
    if (tree.primIndices.size() <= 1 || count <= 1) return tree;
    const auto becomesLeaf = [&](uint32_t i) {
        return tree.nodes[i].isLeaf() || collapseChoice(tree.nodes.data(), i).asLeaf;
    };
    std::vector<uint8_t> kept(count, 0);
    std::vector<uint32_t> stack{0};
    while (!stack.empty()) {
        const uint32_t i = stack.back();
        stack.pop_back();
        kept[i] = 1;
        if (!becomesLeaf(i)) {
            stack.push_back(tree.nodes[i].leftOrFirst);
            stack.push_back(tree.nodes[i].leftOrFirst + 1);
        }
    }
    std::vector<uint32_t> slot(count, 0);
    uint32_t nextSlot = 1;
    for (uint32_t i = 1; i < count; i += 2) {
        if (!kept[i]) continue;
        slot[i] = nextSlot;
        slot[i + 1] = nextSlot + 1;
        nextSlot += 2;
    }
    Bvh out;
    out.nodes.resize(nextSlot);
    for (uint32_t i = 0; i < count; ++i) {
        if (!kept[i]) continue;
        BvhNode node = tree.nodes[i];
        if (becomesLeaf(i)) {
            const uint32_t first = uint32_t(out.primIndices.size());
            forEachSmallSubtreeLeaf(tree.nodes.data(), i, [&](const BvhNode& leaf) {
                for (uint32_t k = 0; k < leaf.count; ++k)
                    out.primIndices.push_back(tree.primIndices[leaf.leftOrFirst + k]);
            });
            node.leftOrFirst = first;
            node.count = uint32_t(out.primIndices.size()) - first;
        } else {
            node.leftOrFirst = slot[node.leftOrFirst];
        }
        out.nodes[slot[i]] = node;
    }
    return out;
}

// Two trees equal bit for bit: nodes and primitive lists.
inline void expectSameTree(const Bvh& actual, const Bvh& expected) {
    ASSERT_EQ(actual.nodes.size(), expected.nodes.size());
    EXPECT_EQ(
        std::memcmp(actual.nodes.data(), expected.nodes.data(), expected.nodes.size() * sizeof(BvhNode)), 0)
        << "the nodes differ";
    EXPECT_EQ(actual.primIndices, expected.primIndices);
}

// `tree` uploaded, collapsed on the device by BvhLeafCollapse's own passes (no builder's
// choices), and downloaded.
inline Bvh collapseOnDevice(cuda::BvhLeafCollapse& collapse, const Bvh& tree, const TestStream& s) {
    cuda::DeviceBuffer<BvhNode> nodes;
    cuda::DeviceBuffer<uint32_t> primIndices;
    nodes.upload(tree.nodes, s.stream);
    primIndices.upload(tree.primIndices, s.stream);
    const uint32_t primCount = uint32_t(tree.primIndices.size());
    const uint32_t kept =
        collapse.collapse(nodes.data(), uint32_t(tree.nodes.size()), primIndices.data(), primCount, s.stream);
    s.sync();  // the collapse's last copies are queued on the stream, which cudaMemcpy does not wait for
    Bvh out;
    nodes.download(out.nodes);
    primIndices.download(out.primIndices);
    out.nodes.resize(kept);
    return out;
}

// A tree of `boxes` built on the device with `builder`, downloaded as built and again after
// BvhLeafCollapse on the device, as the backend runs them: built into the collapse's scratch and
// collapsed into buffers of their own, poisoned first so that an entry the collapse leaves
// unwritten shows; it takes the builder's choices where it gives them (the PLOC builders:
// subtreeChoices()).
template <class Builder>
std::pair<Bvh, Bvh> buildAndCollapseOnDevice(Builder& builder, cuda::BvhLeafCollapse& collapse,
                                             const std::vector<Aabb>& boxes, const TestStream& s) {
    const uint32_t n = uint32_t(boxes.size()), nodeCount = cuda::lbvhNodeCount(n);
    cuda::DeviceBuffer<Aabb> deviceBoxes;
    deviceBoxes.upload(boxes, s.stream);
    const cuda::BvhLeafCollapse::BuildScratch built = collapse.buildScratch(nodeCount, n);
    builder.build(deviceBoxes.data(), n, built.nodes, built.primIndices, s.stream);
    s.sync();
    std::pair<Bvh, Bvh> trees;
    trees.first.nodes.resize(nodeCount);
    trees.first.primIndices.resize(n);
    PT_CUDA_CHECK(cudaMemcpy(trees.first.nodes.data(), built.nodes, nodeCount * sizeof(BvhNode),
                             cudaMemcpyDeviceToHost));
    PT_CUDA_CHECK(cudaMemcpy(trees.first.primIndices.data(), built.primIndices, n * sizeof(uint32_t),
                             cudaMemcpyDeviceToHost));
    cuda::DeviceBuffer<BvhNode> nodes(nodeCount);
    cuda::DeviceBuffer<uint32_t> primIndices(std::max(n, 1u));
    PT_CUDA_CHECK(cudaMemsetAsync(nodes.data(), 0xFF, nodes.bytes(), s.stream));
    PT_CUDA_CHECK(cudaMemsetAsync(primIndices.data(), 0xFF, primIndices.bytes(), s.stream));
    const uint32_t kept = collapse.collapseInto(built.nodes, nodeCount, built.primIndices, n, nodes.data(),
                                                primIndices.data(), s.stream, builder.subtreeChoices());
    s.sync();
    nodes.download(trees.second.nodes);
    primIndices.download(trees.second.primIndices);
    trees.second.nodes.resize(kept);
    trees.second.primIndices.resize(n);
    return trees;
}

// The box every node of `bvh` must hold: the exact union of its primitives' boxes, computed
// from scratch in post-order (node indices say nothing about the order: an LBVH's children
// may precede their parent).
inline std::vector<Aabb> exactNodeBoxes(const Bvh& bvh, const std::vector<Aabb>& primBoxes) {
    std::vector<Aabb> exact(bvh.nodes.size());
    if (bvh.primIndices.empty()) return exact;
    std::vector<std::pair<uint32_t, bool>> stack{{0u, false}};  // (node, children done)
    while (!stack.empty()) {
        const auto [index, childrenDone] = stack.back();
        stack.pop_back();
        const BvhNode& node = bvh.nodes[index];
        if (node.isLeaf()) {
            for (uint32_t k = node.leftOrFirst; k < node.leftOrFirst + node.count; ++k) {
                exact[index].grow(primBoxes[bvh.primIndices[k]]);
            }
        } else if (childrenDone) {
            exact[index] = exact[node.leftOrFirst];
            exact[index].grow(exact[node.leftOrFirst + 1]);
        } else {
            stack.push_back({index, true});
            stack.push_back({node.leftOrFirst, false});
            stack.push_back({node.leftOrFirst + 1, false});
        }
    }
    return exact;
}

inline std::vector<TriangleIndices> triangleIndices(const Mesh& mesh) {
    std::vector<TriangleIndices> triangles(mesh.indices.size() / 3);
    for (size_t t = 0; t < triangles.size(); ++t) {
        triangles[t] = {mesh.indices[3 * t], mesh.indices[3 * t + 1], mesh.indices[3 * t + 2]};
    }
    return triangles;
}

// One triangle mesh, one identity instance, a TLAS of one leaf, and `blas` as its BLAS: the
// host scene in which the shared traversal walks a downloaded device-built or refitted tree.
struct OneMeshScene {
    std::vector<Vec3> positions;
    std::vector<TriangleIndices> triangles;
    Bvh blas;
    BlasRef blasRef{};
    RenderInstance instance{};
    BvhNode tlasRoot{};
    uint32_t tlasIndex = 0;

    OneMeshScene(const Mesh& mesh, Bvh tree)
        : positions(mesh.positions), triangles(triangleIndices(mesh)), blas(std::move(tree)) {
        blasRef.nodeCount = uint32_t(blas.nodes.size());
        blasRef.primitiveCount = uint32_t(triangles.size());
        blasRef.kind = GeometryKind::Triangles;
        const Aabb box = instanceBounds(blas.nodes[0], instance.objectToWorld);
        tlasRoot.lo = box.lo;
        tlasRoot.hi = box.hi;
        tlasRoot.leftOrFirst = 0;
        tlasRoot.count = 1;
    }
    OneMeshScene(const OneMeshScene&) = delete;

    RenderScene view() const {
        RenderScene s;
        s.positions = {positions.data(), uint32_t(positions.size())};
        s.triangles = {triangles.data(), uint32_t(triangles.size())};
        s.blases = {&blasRef, 1};
        s.blasNodes = {blas.nodes.data(), uint32_t(blas.nodes.size())};
        s.blasPrimIndices = {blas.primIndices.data(), uint32_t(blas.primIndices.size())};
        s.instances = {&instance, 1};
        s.tlasNodes = {&tlasRoot, 1};
        s.tlasInstanceIndices = {&tlasIndex, 1};
        return s;
    }
};

// Closest hits through `tree` over `mesh` equal brute force for random rays (half aimed at
// triangles); returns the number of failures (each also a gtest failure, capped).
inline int compareClosestHits(const Mesh& mesh, Bvh tree, uint32_t rays, Rng& rng) {
    const OneMeshScene scene(mesh, std::move(tree));
    const RenderScene view = scene.view();
    int failures = 0;
    uint32_t hits = 0;
    for (uint32_t i = 0; i < rays; ++i) {
        Ray ray = i % 2 ? randomRay(rng, Vec3(-1.5f), Vec3(1.5f))
                        : rayAtTriangle(rng, mesh, Vec3(-1.5f), Vec3(1.5f));
        if (i % 5 == 4) ray.tMax = rng.uniform(0.0f, 2.0f);
        hits += expectBvhMatchesBruteForce(view, ray, failures);
    }
    EXPECT_GT(hits, rays / 4) << "the rays should hit often enough to test something";
    return failures;
}

}  // namespace pt::test
