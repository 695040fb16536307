// The CPU's 8-wide walk loop (issue 21), included twice on purpose, so no include guard: by
// wide_walk.h into namespace pt, where the node test is SSE's, and by wide_walk_avx2.h into
// namespace pt::avx2 under an AVX2 target pragma (in wide_walk_avx2.cpp and
// packet_walk_avx2.cpp), where it is one 256-bit test. Each copy calls
// the WideSlabRay, wideSlabRay and intersectWideNode of the namespace it is included in, and
// its code is compiled for that namespace's instruction set; everything else comes from pt.
// Included after those three are declared, inside the namespace; it includes nothing itself.
// Calls to the per-namespace functions are written (f)(args): the parentheses turn off
// argument-dependent lookup, which would also find pt's copy through the arguments' types.

// walkBvh over the wide tree `nodes` from node `root`: `leaf(first, count, tMax)` as there. The
// nearest child hit is taken next without a trip through the stack (a node whose ray hits one
// child only pushes nothing); the order of visits is the binary walk's nearest-first order,
// but for `anyHit`, which takes the children in slot order.
template <class LeafFn, class Count>
bool walkWideBvh(const WideBvhNode* nodes, uint32_t root, const TraversalRay& ray, float& tMax, LeafFn& leaf,
                 Count count, bool anyHit) {
    const WideSlabRay slab = (wideSlabRay)(ray);
    WideWalkEntry stack[kWideStackSize + 1];
    uint32_t size = 0;
    WideWalkEntry current{root, 0, 0.0f};
    bool found = false;
    for (;;) {
        count.node();
        if (current.count > 0) {
            if (leaf(current.child, current.count, tMax)) {
                found = true;
                if (anyHit) return true;
            }
        } else {
            const WideBvhNode& node = nodes[current.child];
            alignas(32) float entry[WideBvhNode::kWidth];
            int hits = (intersectWideNode)(slab, node, tMax, entry);
            if (hits != 0 && anyHit) {
                // Any hit ends the walk, and tMax never shrinks: the children are taken in slot
                // order, unsorted (as Embree's any-hit traversal; bench's shadow rays on the 1M
                // sphere, 640x480: 9% faster, and 5% faster than taking the nearest first).
                uint32_t slot = uint32_t(__builtin_ctz(unsigned(hits)));
                for (hits &= hits - 1; hits != 0; hits &= hits - 1) {
                    stack[size++] = {node.child[slot], node.count[slot], entry[slot]};
                    slot = uint32_t(__builtin_ctz(unsigned(hits)));
                }
                current = {node.child[slot], node.count[slot], entry[slot]};
                continue;
            }
            const int rest = hits & (hits - 1);  // the hits but the lowest slot's
            if (hits != 0 && (rest & (rest - 1)) == 0) {
                // One or two children hit (most nodes): the nearer is taken next and the other
                // pushed, by selects rather than the sort's data-dependent jumps (one thread,
                // diffuse rays: 8.17 to 8.72 Mrays/s on a 10k-triangle sphere, 4.74 to 5.14 on the
                // 1M one), the higher slot first on a tie, as the sort orders them. Any-hit walks
                // keep the loop above: through here their shadow rays ran 5% slower.
                const uint32_t low = uint32_t(__builtin_ctz(unsigned(hits)));
                const uint32_t high = rest != 0 ? uint32_t(__builtin_ctz(unsigned(rest))) : low;
                const bool highFirst = entry[high] <= entry[low];
                const uint32_t first = highFirst ? high : low, second = highFirst ? low : high;
                // Written even for one child, and not counted: the stack keeps a spare entry.
                assert(size + (rest != 0) <= kWideStackSize && "BVH deeper than the wide traversal stack");
                stack[size] = {node.child[second], node.count[second], entry[second]};
                size += rest != 0;
                current = {node.child[first], node.count[first], entry[first]};
                continue;
            }
            if (hits != 0) {
                // The hit children farthest first (an insertion sort of at most eight): all but
                // the nearest go on the stack, so the nearest of them is popped next.
                uint32_t order[WideBvhNode::kWidth], n = 0;
                for (; hits != 0; hits &= hits - 1) {
                    const uint32_t slot = uint32_t(__builtin_ctz(unsigned(hits)));
                    uint32_t at = n++;
                    while (at > 0 && entry[order[at - 1]] < entry[slot]) {
                        order[at] = order[at - 1];
                        --at;
                    }
                    order[at] = slot;
                }
                assert(size + n - 1 <= kWideStackSize && "BVH deeper than the wide traversal stack");
                for (uint32_t i = 0; i + 1 < n; ++i) {
                    const uint32_t slot = order[i];
                    stack[size++] = {node.child[slot], node.count[slot], entry[slot]};
                }
                const uint32_t nearest = order[n - 1];
                current = {node.child[nearest], node.count[nearest], entry[nearest]};
                continue;
            }
        }
        // Next: the nearest entry left that the ray can still reach before tMax.
        do {
            if (size == 0) return found;
            current = stack[--size];
        } while (current.entry > tMax * kSlabExitScale);
    }
}

// The walk of a triangle BLAS whose leaves index `blocks` (TriangleBlockLeaf), counted into
// `stats` where it is not null.
inline bool walkTriangleBlocks(const WideBvhNode* nodes, uint32_t root, const TriangleBlock* blocks,
                               const TraversalRay& ray, float& tMax, Hit& hit, TraversalStats* stats,
                               bool anyHit) {
    if (stats) {
        TriangleBlockLeaf<TraversalCounter> leaf{blocks, ray, hit, TraversalCounter{stats}, anyHit};
        return (walkWideBvh)(nodes, root, ray, tMax, leaf, TraversalCounter{stats}, anyHit);
    }
    TriangleBlockLeaf<NoTraversalCount> leaf{blocks, ray, hit, {}, anyHit};
    return (walkWideBvh)(nodes, root, ray, tMax, leaf, NoTraversalCount{}, anyHit);
}
