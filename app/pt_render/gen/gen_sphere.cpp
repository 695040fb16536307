#include "pt_render/gen/gen_sphere.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>

#include "pt_render/gen/gen_noise.h"

namespace pt::cli {

namespace {

// The vertices of the cube's surface lattice {0..r}^3, numbered without duplicates: the 8
// corners, then the interior points of the 12 edges, then those of the 6 faces. Every face
// grid names its seam vertices by lattice point, so neighbouring faces share them.
class CubeLattice {
public:
    explicit CubeLattice(uint32_t r) : r_(r), inner_(r - 1) {}

    uint32_t vertexCount() const { return uint32_t(cubeSphereVertices(r_)); }

    uint32_t idOf(const uint32_t c[3]) const {
        auto onBoundary = [&](int k) { return c[k] == 0 || c[k] == r_; };
        const int boundary = int(onBoundary(0)) + int(onBoundary(1)) + int(onBoundary(2));
        if (boundary == 3)
            return (uint32_t(c[0] == r_) << 2) | (uint32_t(c[1] == r_) << 1) | uint32_t(c[2] == r_);
        if (boundary == 2) {
            const int axis = !onBoundary(0) ? 0 : !onBoundary(1) ? 1 : 2;
            const uint32_t bits =
                (uint32_t(c[(axis + 1) % 3] == r_) << 1) | uint32_t(c[(axis + 2) % 3] == r_);
            return 8 + (uint32_t(axis) * 4 + bits) * inner_ + c[axis] - 1;
        }
        const int axis = onBoundary(0) ? 0 : onBoundary(1) ? 1 : 2;
        const uint32_t face = uint32_t(axis) * 2 + uint32_t(c[axis] == r_);
        return faceBase() + face * inner_ * inner_ + (c[(axis + 1) % 3] - 1) * inner_ + c[(axis + 2) % 3] - 1;
    }

    void pointOf(uint32_t id, uint32_t c[3]) const {
        if (id < 8) {
            for (int k = 0; k < 3; ++k) c[k] = ((id >> (2 - k)) & 1u) * r_;
        } else if (id < faceBase()) {
            const uint32_t edge = (id - 8) / inner_, axis = edge / 4, bits = edge % 4;
            c[axis] = (id - 8) % inner_ + 1;
            c[(axis + 1) % 3] = ((bits >> 1) & 1u) * r_;
            c[(axis + 2) % 3] = (bits & 1u) * r_;
        } else {
            const uint32_t rest = id - faceBase(), face = rest / (inner_ * inner_), axis = face / 2;
            const uint32_t cell = rest % (inner_ * inner_);
            c[axis] = (face % 2) * r_;
            c[(axis + 1) % 3] = cell / inner_ + 1;
            c[(axis + 2) % 3] = cell % inner_ + 1;
        }
    }

    // Grid point (a, b) of face (axis, side). With i, j the axes after `axis` in cyclic order
    // (e_i x e_j = e_axis), steps in a then b turn counter-clockwise about the outward normal.
    void facePoint(int axis, uint32_t side, uint32_t a, uint32_t b, uint32_t c[3]) const {
        c[axis] = side * r_;
        c[(axis + 1) % 3] = side ? a : b;
        c[(axis + 2) % 3] = side ? b : a;
    }

private:
    uint32_t faceBase() const { return 8 + 12 * inner_; }

    uint32_t r_, inner_;
};

constexpr double kQuarterPi = 0.785398163397448309616;

// The equal-angle projection of lattice point c to the unit sphere: spreads the triangles
// more evenly than normalising the cube's points directly.
void latticeDirection(const uint32_t c[3], uint32_t r, double d[3]) {
    for (int k = 0; k < 3; ++k) d[k] = std::tan((2.0 * c[k] / r - 1.0) * kQuarterPi);
    const double inv = 1.0 / std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
    for (int k = 0; k < 3; ++k) d[k] *= inv;
}

// The point at distance 1 + A n(d) along d, and the normal of that radial surface:
// N ~ rho d - grad_t(rho), where grad_t is the gradient's part tangent to the sphere
// (so N . d = rho > 0: the normal always points outward).
void displace(const WaveNoise& noise, double amplitude, const double d[3], Vec3& position, Vec3& normal) {
    double gradient[3];
    const double rho = 1.0 + amplitude * noise.evaluate(d, gradient);
    const double radial = gradient[0] * d[0] + gradient[1] * d[1] + gradient[2] * d[2];
    double n[3];
    for (int k = 0; k < 3; ++k) n[k] = rho * d[k] - amplitude * (gradient[k] - radial * d[k]);
    const double inv = 1.0 / std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    position = {float(rho * d[0]), float(rho * d[1]), float(rho * d[2])};
    normal = {float(n[0] * inv), float(n[1] * inv), float(n[2] * inv)};
}

// The bulge target's offset of vertex p (+Y is up, so x^2 + z^2 over |p|^2 is cos^2(latitude)).
Vec3 bulgeOffset(Vec3 p) { return p * (kBulgeAmplitude * (p.x * p.x + p.z * p.z) / dot(p, p)); }

}  // namespace

uint32_t cubeSphereResolution(uint32_t targetTriangles) {
    uint32_t r = std::max(1u, uint32_t(std::lround(std::sqrt(double(targetTriangles) / 12.0))));
    // Rounding the root is not rounding the count: check the neighbours.
    auto miss = [&](uint32_t candidate) {
        const double t = double(cubeSphereTriangles(candidate));
        return std::abs(t - double(targetTriangles));
    };
    if (r > 1 && miss(r - 1) < miss(r)) --r;
    if (miss(r + 1) < miss(r)) ++r;
    return r;
}

Mesh generateDisplacedSphere(const SphereSpec& spec, const ProgressFn& progress) {
    const uint32_t r = cubeSphereResolution(spec.targetTriangles);
    const CubeLattice lattice(r);
    const WaveNoise noise(spec.seed);
    Mesh mesh;
    mesh.name = "displaced sphere";
    mesh.positions.resize(lattice.vertexCount());
    mesh.normals.resize(lattice.vertexCount());
    mesh.indices.resize(size_t(cubeSphereTriangles(r)) * 3);

    // Vertices cost most (the noise); they go in slices so progress is reported from this
    // thread while TBB fills each slice.
    constexpr uint32_t kSlices = 100;
    const uint32_t count = lattice.vertexCount();
    for (uint32_t slice = 0; slice < kSlices; ++slice) {
        reportProgress(progress, "generate", 0.95 * slice / kSlices);
        const uint32_t begin = uint32_t(uint64_t(count) * slice / kSlices);
        const uint32_t end = uint32_t(uint64_t(count) * (slice + 1) / kSlices);
        tbb::parallel_for(tbb::blocked_range<uint32_t>(begin, end),
                          [&](const tbb::blocked_range<uint32_t>& range) {
                              for (uint32_t id = range.begin(); id != range.end(); ++id) {
                                  uint32_t c[3];
                                  double d[3];
                                  lattice.pointOf(id, c);
                                  latticeDirection(c, r, d);
                                  displace(noise, spec.amplitude, d, mesh.positions[id], mesh.normals[id]);
                              }
                          });
    }

    // One task per grid row of a face; each row owns a contiguous run of the index array.
    tbb::parallel_for(tbb::blocked_range<uint32_t>(0, 6 * r), [&](const tbb::blocked_range<uint32_t>& rows) {
        for (uint32_t row = rows.begin(); row != rows.end(); ++row) {
            const int axis = int(row / r / 2);
            const uint32_t side = (row / r) % 2, b = row % r;
            uint32_t* out = mesh.indices.data() + size_t(row) * r * 6;
            for (uint32_t a = 0; a < r; ++a) {
                uint32_t c[3];
                uint32_t corner[4];
                const uint32_t steps[4][2] = {{a, b}, {a + 1, b}, {a + 1, b + 1}, {a, b + 1}};
                for (int k = 0; k < 4; ++k) {
                    lattice.facePoint(axis, side, steps[k][0], steps[k][1], c);
                    corner[k] = lattice.idOf(c);
                }
                const uint32_t quad[6] = {corner[0], corner[1], corner[2], corner[0], corner[2], corner[3]};
                out = std::copy(quad, quad + 6, out);
            }
        }
    });
    reportProgress(progress, "generate", 1.0);
    return mesh;
}

void addBulgeTarget(Mesh& sphere) {
    MorphTarget bulge;
    bulge.name = "bulge";
    bulge.positionDeltas.resize(sphere.positions.size());
    std::transform(sphere.positions.begin(), sphere.positions.end(), bulge.positionDeltas.begin(),
                   bulgeOffset);
    sphere.morphTargets = {std::move(bulge)};
    sphere.morphWeights = sphere.defaultMorphWeights = {0.0f};
    sphere.basePositions = sphere.positions;
    sphere.baseNormals = sphere.normals;
}

}  // namespace pt::cli
