#pragma once
// KHR_materials_anisotropy's direction at a shading point: the BSDF stretches its roughness along
// the shading frame's x (bsdf.h), so the frame is turned about its normal until x is the
// material's direction, given in the tangent space of the mesh (the TANGENT attribute, or the
// UV derivatives; surface_hit.h's objectTangent), as normal maps are.
#include "render/integrator/surface_hit.h"
#include "render/materials/bsdf.h"
#include "render/math/frame.h"

namespace pt {

// `frame` turned so that its tangent is the anisotropy direction; `frame` itself where the
// material is isotropic there or the surface has no tangent space (then the direction is
// undefined: the one the frame happens to have stands in).
template <FeatureSet kF = kAllFeatures>
PT_HD Frame anisotropicFrame(const RenderScene& scene, const Hit& hit, const SurfaceHit& s,
                             const BsdfParams& p, const Frame& frame) {
    if (!hasFeature<kF>(feature::kAnisotropy) || !(p.anisotropy > 0.0f)) return frame;
    Vec3 t, b;
    if (!worldTangentFrame(scene, hit, s, t, b)) return frame;
    // In the tangent plane already: t and b are orthogonal to the normal, n or -n alike.
    Vec3 direction = t * p.anisotropyDirection.x + b * p.anisotropyDirection.y;
    if (!(lengthSquared(direction) > 0.0f) || !isFinite(direction)) return frame;
    direction = normalize(direction);
    return {direction, cross(frame.normal, direction), frame.normal};
}

}  // namespace pt
