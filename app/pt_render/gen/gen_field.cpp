#include "pt_render/gen/gen_field.h"

#include <algorithm>
#include <cmath>

#include "pt_render/gen/gen_random.h"
#include "render/math/affine.h"

namespace pt::cli {

namespace {

constexpr double kMinScale = 0.7, kMaxScale = 1.2, kJitter = 0.2;

// A uniformly distributed rotation (Shoemake, "Uniform random rotations", Graphics Gems III).
Vec4 randomRotation(GenRandom& random) {
    const double u1 = random.uniform(), u2 = random.uniform(0.0, 6.283185307179586),
                 u3 = random.uniform(0.0, 6.283185307179586);
    const double a = std::sqrt(1.0 - u1), b = std::sqrt(u1);
    return {float(a * std::sin(u2)), float(a * std::cos(u2)), float(b * std::sin(u3)),
            float(b * std::cos(u3))};
}

}  // namespace

FieldLayout layoutField(const Mesh& mesh, const FieldSpec& spec) {
    Vec3 lo = mesh.positions[0], hi = mesh.positions[0];
    for (const Vec3& p : mesh.positions) {
        lo = vmin(lo, p);
        hi = vmax(hi, p);
    }
    const Vec3 pivot = (lo + hi) * 0.5f;
    float meshRadius = 0.0f;
    for (const Vec3& p : mesh.positions) meshRadius = std::max(meshRadius, length(p - pivot));
    if (!(meshRadius > 0.0f)) meshRadius = 1.0f;  // a degenerate mesh: still a usable grid

    FieldLayout layout;
    layout.spacing = spec.spacing.value_or(4.0 * meshRadius);
    const uint32_t columns = uint32_t(std::ceil(std::sqrt(double(spec.count))));
    const uint32_t rows = (spec.count + columns - 1) / columns;
    GenRandom random(spec.seed ^ 0x6669656c64ull);  // "field": its own stream of the seed
    layout.instances.reserve(spec.count);
    layout.lo = Vec3(1e30f);
    layout.hi = Vec3(-1e30f);
    for (uint32_t i = 0; i < spec.count; ++i) {
        const double x = (double(i % columns) - 0.5 * (columns - 1)) * layout.spacing;
        const double z = (double(i / columns) - 0.5 * (rows - 1)) * layout.spacing;
        const double jx = random.uniform(-kJitter, kJitter) * layout.spacing;
        const double jz = random.uniform(-kJitter, kJitter) * layout.spacing;
        GenNode node;
        node.rotation = randomRotation(random);
        node.scale = float(random.uniform(kMinScale, kMaxScale));
        // Place the pivot, not the mesh's origin, at the grid point.
        const Vec3 spot{float(x + jx), 0.0f, float(z + jz)};
        node.translation = spot - rotationTransform(node.rotation).transformVector(pivot * node.scale);
        layout.instances.push_back(node);
        const Vec3 reach(node.scale * meshRadius);
        layout.lo = vmin(layout.lo, spot - reach);
        layout.hi = vmax(layout.hi, spot + reach);
    }
    return layout;
}

}  // namespace pt::cli
