#pragma once
// The Lambertian base of a dielectric under its GGX specular layer (glTF's diffuse_brdf inside
// fresnel_mix). glTF mixes by the Fresnel of each direction pair's half vector, which gains
// energy at grazing angles (a smooth white plastic would reflect almost 2). Here the base is
// scaled instead by the energy the layer leaves, reciprocally (Kelemen and Szirmay-Kalos 2001;
// Kulla and Conty 2017):
//   f = baseColor / pi * (1 - E(mu_o)) (1 - E(mu_i)) / (1 - E_avg)
// where E is the layer's directional albedo (specular_albedo.h) and E_avg its cosine-weighted
// average, so the base reflects exactly baseColor (1 - E(mu_o)) and the sum never exceeds 1.
// With F0 = F90 = 0 (KHR_materials_specular factor 0) it is exactly Lambertian.
#include "render/materials/specular_albedo.h"

namespace pt {

struct DiffuseLayer {
    Vec3 layerF0, layerF90;  // Schlick Fresnel of the specular layer above
    float layerAlpha;        // its GGX alpha
};

// (1 - E(mu)) per channel, from the layer's albedo split at mu (ggxSpecularAlbedo).
PT_HD Vec3 layerTransmittance(const DiffuseLayer& d, SpecularAlbedo albedo) {
    return vmax(Vec3(1.0f) - schlickAlbedo(albedo, d.layerF0, d.layerF90), Vec3(0.0f));
}
PT_HD Vec3 layerTransmittance(const DiffuseLayer& d, float mu) {
    return layerTransmittance(d, ggxSpecularAlbedo(mu, d.layerAlpha));
}

// The wo-dependent factor (1 - E(mu_o)) / (1 - E_avg) per channel, given 1 - E(mu_o)
// (0 where E_avg reaches 1).
PT_HD Vec3 diffuseLayerScale(const DiffuseLayer& d, Vec3 transmittanceO) {
    const Vec3 avg =
        Vec3(1.0f) - schlickAlbedo(ggxSpecularAlbedoAverage(d.layerAlpha), d.layerF0, d.layerF90);
    const Vec3 t = transmittanceO;
    return {avg.x > 1e-6f ? t.x / avg.x : 0.0f, avg.y > 1e-6f ? t.y / avg.y : 0.0f,
            avg.z > 1e-6f ? t.z / avg.z : 0.0f};
}

// f * cos(wi) given the resolved wo-dependent weight `scaledAlbedo` = baseColor * diffuseLayerScale.
PT_HD Vec3 evalLayeredDiffuse(const DiffuseLayer& d, Vec3 scaledAlbedo, Vec3 wi) {
    if (wi.z <= 0.0f) return Vec3(0.0f);
    return scaledAlbedo * layerTransmittance(d, wi.z) * (kInvPi * wi.z);
}

}  // namespace pt
