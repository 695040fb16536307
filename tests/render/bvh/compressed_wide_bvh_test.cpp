// The GPU's compressed 8-wide BVH (render/bvh/compressed_wide_bvh.h), on the host: the collapse
// keeps every primitive once, interior children consecutive, leaves (binary subtrees of a few
// primitives) within the walk's 32 primitive bits; every quantised box holds its binary box with a grid step
// of margin; slots face the direction their child lies in; the walk visits fewer nodes than the binary one
// for the same hits; a host refit reaches the quantised boxes. (Its hits against brute force are the Layouts/
// suites of traversal_test.cpp, two_level_traversal_test.cpp and watertight_test.cpp, which walk it on the
// CPU with the code the CUDA kernels run.)
#include "render/bvh/compressed_wide_bvh.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <string>
#include <vector>

#include "render/bvh/binned_sah_builder.h"
#include "render/bvh/bvh_test_util.h"
#include "render/bvh/compressed_wide_quantize.h"
#include "render/bvh/compressed_wide_walk.h"
#include "render/compile/host_refit.h"
#include "render/compile/wide_blases.h"

namespace pt {
namespace {

using test::Rng;

Bvh buildSoupBvh(test::SoupKind kind, uint32_t triangles, Rng& rng, Vec3 offset = Vec3(0.0f),
                 float scale = 1.0f) {
    Mesh mesh = test::makeSoup(kind, triangles, rng);
    for (Vec3& p : mesh.positions) p = p * scale + offset;
    const std::vector<Aabb> boxes = test::triangleBounds(mesh);
    return buildBinnedSahBvh(boxes.data(), uint32_t(boxes.size()));
}

// The primitive-index entries under binary node `n`, left to right.
std::vector<uint32_t> subtreeEntries(const Bvh& bvh, uint32_t n) {
    const BvhNode& node = bvh.nodes[n];
    if (node.isLeaf()) {
        return {bvh.primIndices.begin() + node.leftOrFirst,
                bvh.primIndices.begin() + node.leftOrFirst + node.count};
    }
    std::vector<uint32_t> entries = subtreeEntries(bvh, node.leftOrFirst);
    const std::vector<uint32_t> right = subtreeEntries(bvh, node.leftOrFirst + 1);
    entries.insert(entries.end(), right.begin(), right.end());
    return entries;
}

// A plane q steps from the origin, in double: exact for the float origin and power-of-two step.
double decode(float origin, uint8_t exponent, uint8_t q) {
    return double(origin) + double(exponentStep(exponent)) * double(q);
}

// Meshes for the quantised boxes: a unit scene, a tiny mesh far from the origin (steps near the
// coordinates' ulps), a huge one, a huge one far out (rays from 1e5 of its sizes away start
// about 2e16 off, short of the 1e18 up to which the compressed walk's offsets cannot
// overflow), and needles (boxes flat along some axes).
struct BoxCase {
    test::SoupKind kind;
    Vec3 offset;
    float scale;
};
const BoxCase kBoxCases[] = {{test::SoupKind::Uniform, Vec3(0.0f), 1.0f},
                             {test::SoupKind::Clustered, Vec3(4.0e4f, -3.0e4f, 1.0e3f), 1.0e-3f},
                             {test::SoupKind::Uniform, Vec3(0.0f), 1.0e6f},
                             {test::SoupKind::Clustered, Vec3(3.0e12f, -2.0e12f, 1.0e12f), 1.0e11f},
                             {test::SoupKind::Needles, Vec3(1.0f, 2.0f, 3.0f), 1.0f}};

TEST(CompressedWideBvh, TheCollapseKeepsEveryPrimitiveOnceInConsecutiveChildren) {
    Rng rng(5);
    for (const uint32_t triangles : {1u, 2u, 9u, 100u, 5000u, 30000u}) {
        for (const test::SoupKind kind : {test::SoupKind::Uniform, test::SoupKind::CoincidentCentroids}) {
            SCOPED_TRACE(std::to_string(triangles) + " triangles, " + test::soupName(kind));
            const Bvh bvh = buildSoupBvh(kind, triangles, rng);
            const CompressedWideBvh wide =
                compressToWide(bvh.nodes.data(), uint32_t(bvh.nodes.size()), bvh.primIndices.data());
            std::vector<uint32_t> prims = wide.primIndices;
            std::sort(prims.begin(), prims.end());
            ASSERT_EQ(prims.size(), triangles);
            for (uint32_t i = 0; i < triangles; ++i)
                ASSERT_EQ(prims[i], i) << "a primitive missing or repeated";
            uint32_t children = 0, leafPrims = 0;
            for (size_t n = 0; n < wide.nodes.size(); ++n) {
                const CompressedWideNode& node = wide.nodes[n];
                uint32_t interior = 0, nodePrims = 0, bits = 0;
                for (uint32_t s = 0; s < CompressedWideNode::kWidth; ++s) {
                    const uint32_t source = wide.sourceNodes[n * CompressedWideNode::kWidth + s];
                    const bool isInterior = (node.interiorMask >> s) & 1u;
                    if (source == kNoSourceNode) {
                        EXPECT_FALSE(isInterior);
                        EXPECT_EQ(node.leafCount(s), 0u);
                        continue;
                    }
                    const BvhNode& from = bvh.nodes.at(source);
                    EXPECT_FALSE(from.isLeaf() && isInterior) << "a binary leaf stays a leaf";
                    if (isInterior) {
                        // Its node is the next of the consecutive children, collapsed from
                        // `from`: its slots' boxes make up exactly from's box.
                        const uint32_t child = node.childBase + interior++;
                        ASSERT_LT(child, wide.nodes.size());
                        Aabb covered;
                        for (uint32_t c = 0; c < CompressedWideNode::kWidth; ++c) {
                            const uint32_t grand = wide.sourceNodes[child * CompressedWideNode::kWidth + c];
                            if (grand != kNoSourceNode)
                                covered.grow(Aabb{bvh.nodes[grand].lo, bvh.nodes[grand].hi});
                        }
                        EXPECT_TRUE(covered.lo == from.lo && covered.hi == from.hi) << "child " << child;
                        continue;
                    }
                    // A leaf holds its binary subtree's entries, in their order (a subtree of
                    // few primitives may be one leaf).
                    const std::vector<uint32_t> entries = subtreeEntries(bvh, source);
                    ASSERT_EQ(node.leafCount(s), entries.size());
                    EXPECT_LE(entries.size(), CompressedWideNode::kMaxLeafSize);
                    const uint32_t mask = ((1u << node.leafCount(s)) - 1u) << node.leafOffset(s);
                    EXPECT_EQ(bits & mask, 0u) << "two leaves share primitive bits";
                    bits |= mask;
                    EXPECT_LE(node.leafOffset(s) + node.leafCount(s), 32u);
                    for (uint32_t i = 0; i < entries.size(); ++i) {
                        EXPECT_EQ(wide.primIndices.at(node.primBase + node.leafOffset(s) + i), entries[i]);
                    }
                    nodePrims += node.leafCount(s);
                }
                children += interior;
                leafPrims += nodePrims;
            }
            EXPECT_EQ(children + 1, wide.nodes.size()) << "every node but the root hangs from one slot";
            EXPECT_EQ(leafPrims, triangles);
            if (triangles >= 5000) {
                EXPECT_LE(wide.nodes.size() * 5, bvh.nodes.size()) << "about eight children a node";
            }
        }
    }
}

TEST(CompressedWideBvh, QuantisedBoxesHoldTheirBinaryBoxesWithAStepOfMargin) {
    Rng rng(9);
    for (const BoxCase c : kBoxCases) {
        const Bvh bvh = buildSoupBvh(c.kind, 4000, rng, c.offset, c.scale);
        const CompressedWideBvh wide =
            compressToWide(bvh.nodes.data(), uint32_t(bvh.nodes.size()), bvh.primIndices.data());
        int failures = 0;
        for (size_t n = 0; n < wide.nodes.size(); ++n) {
            const CompressedWideNode& node = wide.nodes[n];
            for (uint32_t s = 0; s < CompressedWideNode::kWidth; ++s) {
                const uint32_t source = wide.sourceNodes[n * CompressedWideNode::kWidth + s];
                if (source == kNoSourceNode) continue;
                const BvhNode& box = bvh.nodes[source];
                using P = CompressedWideNode::BoxPlane;
                const uint8_t lo[3] = {node.plane(P::kLoX, s), node.plane(P::kLoY, s),
                                       node.plane(P::kLoZ, s)};
                const uint8_t hi[3] = {node.plane(P::kHiX, s), node.plane(P::kHiY, s),
                                       node.plane(P::kHiZ, s)};
                for (int a = 0; a < 3; ++a) {
                    const double step = exponentStep(node.exponent[a]);
                    const double margin = 0.99 * step;
                    const bool ok =
                        decode(node.origin[a], node.exponent[a], lo[a]) <= double(box.lo[a]) - margin &&
                        decode(node.origin[a], node.exponent[a], hi[a]) >= double(box.hi[a]) + margin &&
                        step >= double(box.hi[a] - box.lo[a]) / 256.0;
                    if (!ok && ++failures <= 5) {
                        ADD_FAILURE()
                            << "node " << n << " slot " << s << " axis " << a << ": box [" << box.lo[a]
                            << ", " << box.hi[a] << "], quantised [" << int(lo[a]) << ", " << int(hi[a])
                            << "] steps of " << step << " from " << node.origin[a];
                    }
                }
            }
        }
        EXPECT_EQ(failures, 0);
    }
}

// The slab test in double of `ray` (the float origin and direction, tMax) against the box
// [lo, hi]: whether it enters it within [0, tMax], up to `slack` relative to the distances.
bool entersInDouble(Vec3 origin, Vec3 direction, double tMax, const double lo[3], const double hi[3],
                    double slack = 0.0) {
    double tNear = 0.0, tFar = tMax;
    for (int a = 0; a < 3; ++a) {
        const double inverse = 1.0 / double(direction[a]);
        const double t0 = (lo[a] - double(origin[a])) * inverse, t1 = (hi[a] - double(origin[a])) * inverse;
        tNear = std::max(tNear, std::min(t0, t1));
        tFar = std::min(tFar, std::max(t0, t1));
    }
    return tNear <= tFar + slack * std::max(std::fabs(tNear), std::fabs(tFar));
}

// The GPU's child test (compressedSlotHits: a plane in one fused multiply-add, its 2^15 bias
// folded into the node's offsets; the host's fmaf rounds as the GPU's FFMA does) against exact
// slab tests in double: every binary box a ray enters must be hit (the quantised box holds it
// with a step of margin), and every slot hit must be one whose quantised box the ray enters,
// give or take a hundredth of a step and the exit scale's slack. Rays from inside the scene,
// from far outside it (distances where a float's ulp nears a grid step), and nearly along an
// axis (inverse directions up to the compressed walk's limit); the meshes of kBoxCases.
TEST(CompressedWideBvh, TheGpuChildTestHoldsEveryBoxItsRayEntersAndNoFarOther) {
    Rng rng(21);
    int64_t entered = 0, missed = 0, notTaken = 0;
    for (const BoxCase c : kBoxCases) {
        const Bvh bvh = buildSoupBvh(c.kind, 3000, rng, c.offset, c.scale);
        const CompressedWideBvh wide =
            compressToWide(bvh.nodes.data(), uint32_t(bvh.nodes.size()), bvh.primIndices.data());
        const Vec3 lo = bvh.nodes[0].lo, hi = bvh.nodes[0].hi, centre = (lo + hi) * 0.5f;
        const float size = length(hi - lo);
        int unsound = 0, loose = 0;
        for (int i = 0; i < 600; ++i) {
            Vec3 origin = rng.inBox(lo, hi), direction = rng.unitVector();
            if (i % 3 == 1) {  // from 1e2 to 1e5 sizes away, towards the scene
                origin = centre + rng.unitVector() * (size * std::pow(10.0f, rng.uniform(2.0f, 5.0f)));
                direction = normalize(rng.inBox(lo, hi) - origin);
            } else if (i % 3 == 2) {  // nearly along an axis
                const uint32_t axis = rng.index(3);
                for (uint32_t a = 0; a < 3; ++a) {
                    const float tiny = std::pow(10.0f, rng.uniform(-15.9f, -3.0f));
                    direction[a] = a == axis ? 1.0f : (rng.uniform() < 0.5f ? -tiny : tiny);
                }
            }
            const float tMax = i % 2 ? kInf : rng.uniform(0.0f, 2.0f) * size;
            const TraversalRay ray = makeTraversalRay(origin, direction);
            // A component too small for the compressed walk (an exact zero, where the tiny far mesh
            // is narrower than an ulp and a far origin lines up with it) goes to the binary walk.
            if (!compressedWalkTakes(ray)) {
                ++notTaken;
                continue;
            }
            const CompressedWalkRay r = compressedWalkRay(ray);
            for (uint32_t n = 0; n < wide.nodes.size(); ++n) {
                const uint32_t hits = compressedSlotHits(r, loadCompressedNodeHeader(wide.nodes.data(), n),
                                                         wide.nodes.data(), n, tMax);
                const CompressedWideNode& node = wide.nodes[n];
                for (uint32_t s = 0; s < CompressedWideNode::kWidth; ++s) {
                    const uint32_t source = wide.sourceNodes[n * CompressedWideNode::kWidth + s];
                    if (source == kNoSourceNode) continue;
                    const bool hit = (hits >> s) & 1u;
                    const double binaryLo[3] = {bvh.nodes[source].lo.x, bvh.nodes[source].lo.y,
                                                bvh.nodes[source].lo.z};
                    const double binaryHi[3] = {bvh.nodes[source].hi.x, bvh.nodes[source].hi.y,
                                                bvh.nodes[source].hi.z};
                    const bool enters = entersInDouble(origin, direction, tMax, binaryLo, binaryHi);
                    entered += enters;
                    missed += !hit;
                    using P = CompressedWideNode::BoxPlane;
                    double quantisedLo[3], quantisedHi[3];
                    for (uint32_t a = 0; a < 3; ++a) {
                        const double margin = 0.01 * exponentStep(node.exponent[a]);
                        quantisedLo[a] =
                            decode(node.origin[a], node.exponent[a], node.plane(P(P::kLoX + a), s)) - margin;
                        quantisedHi[a] =
                            decode(node.origin[a], node.exponent[a], node.plane(P(P::kHiX + a), s)) + margin;
                    }
                    const bool nearQuantised = entersInDouble(origin, direction, double(tMax) * (1.0 + 1e-5),
                                                              quantisedLo, quantisedHi, 1e-5);
                    if (enters && !hit && ++unsound <= 3) {
                        ADD_FAILURE() << test::soupName(c.kind) << ": ray " << i << " enters node " << n
                                      << " slot " << s << "'s binary box, not hit";
                    }
                    if (hit && !nearQuantised && ++loose <= 3) {
                        ADD_FAILURE() << test::soupName(c.kind) << ": ray " << i << " hits node " << n
                                      << " slot " << s << ", far from its quantised box";
                    }
                }
            }
        }
        EXPECT_EQ(unsound, 0) << test::soupName(c.kind);
        EXPECT_EQ(loose, 0) << test::soupName(c.kind);
    }
    // Nearly every ray took the compressed walk, and both answers were common: the checks
    // above had cases to catch.
    EXPECT_LT(notTaken, 30);
    EXPECT_GT(entered, 10000);
    EXPECT_GT(missed, 100000);
}

// The byte permutes behind it put byte k of a word under the exponent of 1, exactly.
TEST(CompressedWideBvh, ByteUnderOneIsOnePlusTheByteTimesTwoToTheMinus15) {
    Rng rng(22);
    for (int i = 0; i < 1000; ++i) {
        const uint32_t word = rng.index(0xffffffffu) ^ (rng.index(2) << 31);
        for (uint32_t k = 0; k < 4; ++k) {
            const uint32_t q = (word >> (8 * k)) & 0xffu;
            ASSERT_EQ(byteUnderOne(word, k), 1.0f + float(q) / 32768.0f) << std::hex << word << " byte " << k;
        }
    }
}

// Eight one-triangle clusters at the corners of a cube: one node of eight leaves, each in the
// slot whose direction (bit a set: towards -a) points at its corner.
TEST(CompressedWideBvh, EachChildSitsInTheSlotFacingIt) {
    Mesh mesh;
    for (uint32_t corner = 0; corner < 8; ++corner) {
        const Vec3 c((corner & 1u) ? -1.0f : 1.0f, (corner & 2u) ? -1.0f : 1.0f,
                     (corner & 4u) ? -1.0f : 1.0f);
        const uint32_t base = uint32_t(mesh.positions.size());
        mesh.positions.push_back(c);
        mesh.positions.push_back(c + Vec3(0.05f, 0.0f, 0.0f));
        mesh.positions.push_back(c + Vec3(0.0f, 0.05f, 0.0f));
        mesh.indices.insert(mesh.indices.end(), {base, base + 1, base + 2});
    }
    const std::vector<Aabb> boxes = test::triangleBounds(mesh);
    BvhBuildOptions options;
    options.maxLeafSize = 1;
    const Bvh bvh = buildBinnedSahBvh(boxes.data(), uint32_t(boxes.size()), options);
    const CompressedWideBvh wide =
        compressToWide(bvh.nodes.data(), uint32_t(bvh.nodes.size()), bvh.primIndices.data());
    ASSERT_EQ(wide.nodes.size(), 1u);
    const CompressedWideNode& root = wide.nodes[0];
    for (uint32_t s = 0; s < CompressedWideNode::kWidth; ++s) {
        ASSERT_EQ(root.leafCount(s), 1u);
        const uint32_t triangle = wide.primIndices[root.primBase + root.leafOffset(s)];
        EXPECT_EQ(triangle, s) << "triangle " << triangle << " (corner " << triangle << ") in slot " << s;
    }
}

// The walk's bit tricks against their definitions: a slot's bit moves to slot ^ firstSlot (the
// visiting order), and a leaf's meta byte (count << 5 | offset) gives count bits from offset.
TEST(CompressedWideBvh, VisitingOrderAndLeafBitsFollowTheirDefinitions) {
    for (uint32_t firstSlot = 0; firstSlot < 8; ++firstSlot) {
        for (uint32_t slots = 0; slots < 256; ++slots) {
            uint32_t expected = 0;
            for (uint32_t s = 0; s < 8; ++s) expected |= ((slots >> s) & 1u) << (s ^ firstSlot);
            ASSERT_EQ(inVisitingOrder(slots, firstSlot), expected) << slots << " from slot " << firstSlot;
        }
    }
    for (uint32_t count = 0; count <= CompressedWideNode::kMaxLeafSize; ++count) {
        for (uint32_t offset = 0; offset < 32 && offset + count <= 32; ++offset) {
            uint32_t expected = 0;
            for (uint32_t k = 0; k < count; ++k) expected |= 1u << (offset + k);
            EXPECT_EQ(leafPrimitiveBits(count << 5 | offset), expected) << count << " from " << offset;
        }
    }
}

// The same closest hits through far fewer nodes: what the CUDA traversal walks.
TEST(CompressedWideBvh, TheWalkVisitsFewerNodesForTheSameHits) {
    const auto [binaryStats, wideStats] = test::walkWorkAgainstBinary(test::Layout::Compressed);
    std::cout << "[ figures  ] nodes visited: binary " << binaryStats.nodesVisited << ", compressed "
              << wideStats.nodesVisited << "; primitives tested: binary " << binaryStats.primitivesTested
              << ", compressed " << wideStats.primitivesTested << "\n";
    // Nodes visited (the binary count has its leaves too; measured 2.8x fewer): at least 2x.
    EXPECT_LT(wideStats.nodesVisited * 2, binaryStats.nodesVisited);
    // The SAH-optimal collapse trades node tests for primitive tests at 0.3 of a node each
    // (leaves of up to four gathered from small subtrees: measured 2.0x the binary walk's tests,
    // 1.14x with the greedy collapse), so the work they weigh together is what falls: measured
    // 0.40 of the binary walk's (the greedy collapse 0.43).
    const auto work = [](const TraversalStats& s) {
        return double(s.nodesVisited) + 0.3 * s.primitivesTested;
    };
    EXPECT_LT(work(wideStats), 0.5 * work(binaryStats));
    // That weight is the collapse's own, so the primitive tests are held apart too: leaves of
    // four at most cannot double them much more.
    EXPECT_LT(wideStats.primitivesTested, 2.5 * binaryStats.primitivesTested);
}

// Axis-aligned rays (exact zeros in the direction) walk the binary nodes: their inverse of 1e30
// would overflow the compressed walk's plane offsets on nodes 3.4e8 away. A floor two billion
// units wide under a few small triangles: every straight-down ray must still hit.
TEST(CompressedWideBvh, AxisAlignedRaysHitAFloorFarWiderThanTheirInverseAllows) {
    Rng rng(4);
    Mesh mesh = test::makeSoup(test::SoupKind::Uniform, 200, rng);
    const uint32_t base = uint32_t(mesh.positions.size());
    mesh.positions.push_back({-1.0e9f, -2.0f, -1.0e9f});
    mesh.positions.push_back({1.0e9f, -2.0f, -1.0e9f});
    mesh.positions.push_back({0.0f, -2.0f, 1.0e9f});
    mesh.indices.insert(mesh.indices.end(), {base, base + 1, base + 2});
    const CompiledScene compiled = test::compileSingleMesh(mesh, test::Layout::Compressed);
    EXPECT_FALSE(compressedWalkTakes(makeTraversalRay(Vec3(0.0f), Vec3(0.0f, -1.0f, 0.0f))));
    EXPECT_TRUE(compressedWalkTakes(makeTraversalRay(Vec3(0.0f), Vec3(1e-3f, -1.0f, 0.2f))));
    int failures = 0, hits = 0;
    for (int i = 0; i < 2000; ++i) {
        const Vec3 o(rng.uniform(-3.0f, 3.0f), 10.0f, rng.uniform(-3.0f, 3.0f));
        hits += test::expectBvhMatchesBruteForce(compiled.view(), Ray{o, Vec3(0.0f, -1.0f, 0.0f), kInf},
                                                 failures);
        test::expectBvhMatchesBruteForce(compiled.view(), Ray{o, Vec3(1e-3f, -1.0f, 0.0f), kInf}, failures);
    }
    EXPECT_EQ(failures, 0);
    EXPECT_EQ(hits, 2000) << "the floor lies under every ray";
    // Straight-down rays did the binary walk's work, node for node and test for test.
    const CompiledScene binary = test::compileSingleMesh(mesh, test::Layout::Binary);
    TraversalStats viaCompressed, viaBinary;
    for (int i = 0; i < 200; ++i) {
        const Ray ray{Vec3(rng.uniform(-3.0f, 3.0f), 10.0f, rng.uniform(-3.0f, 3.0f)),
                      Vec3(0.0f, -1.0f, 0.0f), kInf};
        Hit a, b;
        intersectClosest(compiled.view(), ray, a, &viaCompressed);
        intersectClosest(binary.view(), ray, b, &viaBinary);
    }
    EXPECT_EQ(viaCompressed.nodesVisited, viaBinary.nodesVisited);
    EXPECT_EQ(viaCompressed.primitivesTested, viaBinary.primitivesTested);
}

// Moved vertices refit the binary BLAS on the host; the quantised boxes must follow, or rays
// would miss the moved triangles.
TEST(CompressedWideBvh, AHostRefitReachesTheQuantisedBoxes) {
    Rng rng(12);
    Mesh mesh = test::makeSoup(test::SoupKind::Uniform, 3000, rng);
    CompiledScene compiled = test::compileSingleMesh(mesh, test::Layout::Compressed);
    for (Vec3& p : compiled.positions) p = p * 1.5f + Vec3(0.3f, 0.0f, 0.0f);
    for (Vec3& p : mesh.positions) p = p * 1.5f + Vec3(0.3f, 0.0f, 0.0f);
    refitBlasOnHost(compiled, 0);
    refreshWideBlas(compiled, 0);
    int failures = 0, hits = 0;
    for (int i = 0; i < 5000; ++i) {
        hits += test::expectBvhMatchesBruteForce(
            compiled.view(), test::rayAtTriangle(rng, mesh, Vec3(-2.0f), Vec3(2.0f)), failures);
    }
    EXPECT_EQ(failures, 0);
    EXPECT_GT(hits, 4000);
}

}  // namespace
}  // namespace pt
