// The watertight triangle test on a TriangleBlock's lanes and the wide walk's leaf functor over
// such blocks (issue 21), included twice on purpose, so no include guard: by
// triangle_block_intersect.h into namespace pt, where a test takes one block (SSE, four lanes),
// and by wide_walk_avx2.h into namespace pt::avx2 under the AVX2 target pragma, where it takes
// two blocks at once (eight lanes: the eight triangles of a full wide leaf in one pass, where
// SSE takes two). Per-namespace calls are written (f)(args), as in wide_walk_loop.inl, so that
// argument-dependent lookup never finds the other namespace's copy. Each includer first
// declares namespace `lane_ops`: Vector, kCount, the operations below and loadCorner. Included
// inside the namespace; it includes nothing itself.
//
// Each lane performs the scalar test's operations in the scalar test's order (no FMA: the host
// builds with -ffp-contract=off, and the products are separate multiplies), so every lane's t,
// u and v equal intersectTriangle's bit for bit, and hits stay those of the binary walk, of
// brute force and of the GPU. Embree tests its leaves four or eight triangles at a time the
// same way; here the SoA copy also spares the scalar test's three dependent loads (primitive
// index, vertex indices, positions) per triangle.

// The scalar test's rare exact-zero branch for lane `lane`: edge functions redone in double.
inline void exactEdgesOfLane(float (&e)[3][lane_ops::kCount], const float (&x)[3][lane_ops::kCount],
                             const float (&y)[3][lane_ops::kCount], uint32_t lane) {
    const double ax = x[0][lane], ay = y[0][lane], bx = x[1][lane], by = y[1][lane];
    const double cx = x[2][lane], cy = y[2][lane];
    e[0][lane] = float(cx * by - cy * bx);
    e[1][lane] = float(ax * cy - ay * cx);
    e[2][lane] = float(bx * ay - by * ax);
}

// edgeFunction(a, b, c, d) = a * b - c * d in every lane, each product rounded on its own. A
// function, not a lambda: as a lambda GCC 12 refused it in the AVX2 region (-Wpsabi, "AVX
// vector return without AVX enabled changes the ABI").
inline lane_ops::Vector edgeLanes(lane_ops::Vector a, lane_ops::Vector b, lane_ops::Vector c,
                                  lane_ops::Vector d) {
    return lane_ops::sub(lane_ops::mul(a, b), lane_ops::mul(c, d));
}

// intersectTriangle(ray, tMax, ...) on the lanes of block `low` (and of `high`, where a test
// takes two blocks: lanes 4..7): the lanes that hit, as a bit mask, with their t, u and v.
inline int intersectTriangleLanes(const WatertightRay& ray, float tMax, const TriangleBlock& low,
                                  const TriangleBlock& high, lane_ops::Vector& t, lane_ops::Vector& u,
                                  lane_ops::Vector& v) {
    using lane_ops::Vector;
    const Vector originX = lane_ops::set1(ray.origin[ray.kx]), originY = lane_ops::set1(ray.origin[ray.ky]);
    const Vector originZ = lane_ops::set1(ray.origin[ray.kz]);
    const Vector sx = lane_ops::set1(ray.sx), sy = lane_ops::set1(ray.sy), sz = lane_ops::set1(ray.sz);
    // Per corner: a = p - origin in the ray's axes, then sheared (ax = a[kx] - sx * a[kz]).
    Vector x[3], y[3], z[3];
    for (int c = 0; c < 3; ++c) {
        const Vector ax = lane_ops::sub(lane_ops::loadCorner(low, high, c, ray.kx), originX);
        const Vector ay = lane_ops::sub(lane_ops::loadCorner(low, high, c, ray.ky), originY);
        z[c] = lane_ops::sub(lane_ops::loadCorner(low, high, c, ray.kz), originZ);
        x[c] = lane_ops::sub(ax, lane_ops::mul(sx, z[c]));
        y[c] = lane_ops::sub(ay, lane_ops::mul(sy, z[c]));
    }
    Vector e0 = edgeLanes(x[2], y[1], y[2], x[1]);  // weight of p0
    Vector e1 = edgeLanes(x[0], y[2], y[0], x[2]);  // weight of p1
    Vector e2 = edgeLanes(x[1], y[0], y[1], x[0]);  // weight of p2
    const Vector zero = lane_ops::zero();
    const int zeroEdge = lane_ops::mask(lane_ops::bitOr(
        lane_ops::bitOr(lane_ops::equal(e0, zero), lane_ops::equal(e1, zero)), lane_ops::equal(e2, zero)));
    if (zeroEdge != 0) {
        alignas(32) float e[3][lane_ops::kCount], xs[3][lane_ops::kCount], ys[3][lane_ops::kCount];
        lane_ops::store(e[0], e0), lane_ops::store(e[1], e1), lane_ops::store(e[2], e2);
        for (int c = 0; c < 3; ++c) lane_ops::store(xs[c], x[c]), lane_ops::store(ys[c], y[c]);
        for (int mask = zeroEdge; mask != 0; mask &= mask - 1) {
            exactEdgesOfLane(e, xs, ys, uint32_t(__builtin_ctz(unsigned(mask))));
        }
        e0 = lane_ops::load(e[0]), e1 = lane_ops::load(e[1]), e2 = lane_ops::load(e[2]);
    }
    // Mixed signs: the ray passes outside an edge.
    const Vector negative = lane_ops::bitOr(
        lane_ops::bitOr(lane_ops::less(e0, zero), lane_ops::less(e1, zero)), lane_ops::less(e2, zero));
    const Vector positive =
        lane_ops::bitOr(lane_ops::bitOr(lane_ops::greater(e0, zero), lane_ops::greater(e1, zero)),
                        lane_ops::greater(e2, zero));
    const Vector det = lane_ops::add(lane_ops::add(e0, e1), e2);
    Vector valid = lane_ops::bitAndNot(lane_ops::bitAnd(negative, positive), lane_ops::notEqual(det, zero));
    if (lane_ops::mask(valid) == 0) return 0;
    const Vector scaledT = lane_ops::add(
        lane_ops::add(lane_ops::mul(e0, lane_ops::mul(sz, z[0])), lane_ops::mul(e1, lane_ops::mul(sz, z[1]))),
        lane_ops::mul(e2, lane_ops::mul(sz, z[2])));
    // det < 0 ? -scaledT : scaledT, and |det|, by the sign bit (det is never zero here).
    const Vector sign = lane_ops::set1(-0.0f);
    const Vector signedT = lane_ops::bitXor(scaledT, lane_ops::bitAnd(det, sign));
    const Vector absDet = lane_ops::bitAndNot(sign, det);
    const Vector range =
        lane_ops::mul(lane_ops::mul(lane_ops::set1(tMax), absDet), lane_ops::set1(1.0f + 0x1p-20f));
    valid = lane_ops::bitAnd(
        valid, lane_ops::bitAnd(lane_ops::greater(signedT, zero), lane_ops::lessEqual(signedT, range)));
    if (lane_ops::mask(valid) == 0) return 0;
    const Vector invDet = lane_ops::div(lane_ops::set1(1.0f), det);
    t = lane_ops::mul(scaledT, invDet);
    valid = lane_ops::bitAnd(
        valid, lane_ops::bitAnd(lane_ops::greater(t, zero), lane_ops::less(t, lane_ops::set1(tMax))));
    u = lane_ops::mul(e1, invDet);
    v = lane_ops::mul(e2, invDet);
    return lane_ops::mask(valid);
}

// Leaf functor of walkWideBvh for a BLAS of triangles whose wide leaves index TriangleBlocks
// (`first` the first block, `count` its triangles, four a block, in consecutive blocks). The
// same hit as BlasLeaf's over the same primitives: the closest t, ties to the lower primitive,
// which does not depend on the order the lanes are looked at in, nor on whether a second block
// is tested with the first or after it (a lane the first block's hit would have culled is one
// the comparison with tMax below turns away). Every triangle of a test is tested, so all count
// as tested, also where an any-hit query stops at the first.
template <class Count>
struct TriangleBlockLeaf {
    static constexpr uint32_t kBlocksPerTest = lane_ops::kCount / TriangleBlock::kWidth;

    const TriangleBlock* blocks;  // RenderScene::blasTriangleBlocks
    const TraversalRay& ray;
    Hit& hit;
    Count counter;
    bool anyHit;

    bool hitHere = false;  // this walk has found a hit: tMax is that hit's t

    bool operator()(uint32_t first, uint32_t count, float& tMax) {
        bool found = false;
        for (uint32_t b = 0; b * TriangleBlock::kWidth < count; b += kBlocksPerTest) {
            const uint32_t left = count - b * TriangleBlock::kWidth;  // triangles from block b on
            // A test of two blocks with one left takes it twice: each repeat hits where its
            // original does, at the same t and primitive.
            const TriangleBlock& low = blocks[first + b];
            const TriangleBlock& high =
                kBlocksPerTest > 1 && left > TriangleBlock::kWidth ? blocks[first + b + 1] : low;
            if (testBlocks(low, high, left, tMax)) {
                found = true;
                if (anyHit) return true;
            }
        }
        return found;
    }

    // One test's blocks, of whose lanes the first `count` (at most all) are triangles of the leaf.
    bool testBlocks(const TriangleBlock& low, const TriangleBlock& high, uint32_t count, float& tMax) {
        for (uint32_t i = 0; i < count && i < lane_ops::kCount; ++i) counter.primitive();
        const float limit = hitHere ? intAsFloat(floatAsInt(tMax) + 1) : tMax;  // t == tMax too
        lane_ops::Vector t, u, v;
        int hits = (intersectTriangleLanes)(ray.watertight, limit, low, high, t, u, v);
        if (hits == 0) return false;
        alignas(32) float ts[lane_ops::kCount], us[lane_ops::kCount], vs[lane_ops::kCount];
        lane_ops::store(ts, t), lane_ops::store(us, u), lane_ops::store(vs, v);
        bool found = false;
        for (; hits != 0; hits &= hits - 1) {
            const uint32_t lane = uint32_t(__builtin_ctz(unsigned(hits)));
            const uint32_t primitive = lane < TriangleBlock::kWidth
                                           ? low.primitive[lane]
                                           : high.primitive[lane - TriangleBlock::kWidth];
            if (ts[lane] < tMax || (hitHere && ts[lane] == tMax && primitive < hit.primitive)) {
                hit.t = ts[lane], hit.u = us[lane], hit.v = vs[lane], hit.primitive = primitive;
                tMax = ts[lane];
                found = hitHere = true;
                if (anyHit) return true;
            }
        }
        return found;
    }
};
