#pragma once
// Displaced cube-spheres for `pt-render gen`: the six faces of a cube, each an r x r grid,
// projected onto the unit sphere and displaced radially. Seam vertices are shared, so the
// mesh is closed and watertight, wound counter-clockwise seen from outside.
#include <cstdint>

#include "render/scene/scene.h"
#include "render/util/progress.h"

namespace pt::cli {

struct SphereSpec {
    uint32_t targetTriangles = 1000;  // the result has 12 r^2, r the nearest fit (>= 1)
    double amplitude = 0.1;           // radius stays within 1 +- amplitude; in [0, 1)
    uint64_t seed = 0;
};

// r such that 12 r^2 is nearest to `targetTriangles` (at least 1).
uint32_t cubeSphereResolution(uint32_t targetTriangles);
inline uint64_t cubeSphereTriangles(uint32_t r) { return 12ull * r * r; }
inline uint64_t cubeSphereVertices(uint32_t r) { return 6ull * r * r + 2; }

// Positions in object space (radius about 1 at the origin), unit normals of the smooth
// displaced surface (exact, from the noise's gradient), indices. Runs on TBB's threads;
// reports the "generate" stage from the calling thread.
Mesh generateDisplacedSphere(const SphereSpec& spec, const ProgressFn& progress = {});

// The bulge target's largest offset, as a fraction of a vertex's distance from the centre.
constexpr float kBulgeAmplitude = 0.15f;

// Gives the sphere (centred on the origin) one morph target, "bulge", at weight 0 (`gen sphere
// --morph`): at weight w vertex p moves outward by w * kBulgeAmplitude * cos^2(latitude) * p, so
// the equator swells by 15% and the poles stay put. POSITION deltas only (the normals keep their
// base values). The base arrays are filled, so applyMorphWeights accepts the mesh.
void addBulgeTarget(Mesh& sphere);

}  // namespace pt::cli
