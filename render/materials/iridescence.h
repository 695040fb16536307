#pragma once
// KHR_materials_iridescence: the reflectance of a thin dielectric film (soap, oil, the oxide on
// heated metal) over a base of reflectance F0. Light reflected at the film's top and at its
// base interferes; Belcour and Barla, "A Practical Extension to Microfacet Theory for the
// Modeling of Varying Iridescence" (SIGGRAPH 2017) integrate the resulting spectrum against the
// eye's responses in closed form: an Airy sum truncated after two orders, whose spectral terms
// are the Fourier transforms of Gaussian fits to the XYZ matching functions. This is the
// specification's own code (Khronos' Sample Viewer), with Schlick's Fresnel at each interface and
// the base's index derived from its F0, metals included.
//
// The specular lobe evaluates it at each microfacet's cos(wo.h), as Belcour and Barla do; the
// Sample Viewer, a rasteriser, takes cos(n.v) once a pixel.
#include "render/materials/fresnel.h"
#include "render/math/cie_xyz.h"

namespace pt {

struct ThinFilm {
    float weight;     // iridescenceFactor (times its texture): the film's share of the Fresnel term
    float ior;        // the film's index
    float thickness;  // nanometres
};

namespace thin_film_detail {

// The interference of order m at optical path difference opd (nm) with phase shift `shift`, in
// linear Rec.709: the XYZ sensitivities' Fourier transforms (Belcour and Barla 2017, supplemental).
PT_HD Vec3 evalSensitivity(float opd, Vec3 shift) {
    const float phase = 2.0f * kPi * opd * 1e-9f;
    const float phase2 = phase * phase;
    // val * sqrt(2 pi var) of each Gaussian, folded.
    auto term = [&](float amplitude, float position, float variance, float s) {
        return amplitude * sqrtf(2.0f * kPi * variance) * cosf(position * phase + s) *
               expf(-phase2 * variance);
    };
    const Vec3 xyz{term(5.4856e-13f, 1.6810e+06f, 4.3278e+09f, shift.x) +
                       term(9.7470e-14f, 2.2399e+06f, 4.5282e+09f, shift.x),
                   term(4.4201e-13f, 1.7953e+06f, 9.3046e+09f, shift.y),
                   term(5.2481e-13f, 2.2084e+06f, 6.6121e+09f, shift.z)};
    return xyzToLinearRec709(xyz * (1.0f / 1.0685e-7f));
}

PT_HD float iorToF0(float transmitted, float incident) {
    const float r = (transmitted - incident) / (transmitted + incident);
    return r * r;
}

// The index whose F0 against air is f0 (f0 < 1).
PT_HD float f0ToIor(float f0) {
    const float s = sqrtf(clampf(f0, 0.0f, 0.9999f));
    return (1.0f + s) / (1.0f - s);
}

}  // namespace thin_film_detail

// The film's reflectance over a base of reflectance baseF0, seen from air at cos(theta) =
// cosTheta; in [0, 1] per channel.
PT_HD Vec3 thinFilmFresnel(const ThinFilm& film, Vec3 baseF0, float cosTheta) {
    using namespace thin_film_detail;
    cosTheta = clampf(cosTheta, 0.0f, 1.0f);
    // A film thinner than 0.03 nm fades to none (the film's index to the outside's).
    const float t = clampf(film.thickness / 0.03f, 0.0f, 1.0f);
    const float filmIor = 1.0f + (film.ior - 1.0f) * (t * t * (3.0f - 2.0f * t));
    const float sin2Film = (1.0f - cosTheta * cosTheta) / (filmIor * filmIor);
    if (sin2Film >= 1.0f) return Vec3(1.0f);  // total internal reflection (a film below 1)
    const float cosFilm = sqrtf(1.0f - sin2Film);
    // The top interface (air to film), the same both ways.
    const float r12 = schlickWeight(cosTheta) * (1.0f - iorToF0(filmIor, 1.0f)) + iorToF0(filmIor, 1.0f);
    const float t121 = 1.0f - r12;
    const float phi21 = filmIor < 1.0f ? 0.0f : kPi;  // pi - phi12
    // The base (film to base), per channel.
    const Vec3 baseIor{f0ToIor(baseF0.x), f0ToIor(baseF0.y), f0ToIor(baseF0.z)};
    const Vec3 r1{iorToF0(baseIor.x, filmIor), iorToF0(baseIor.y, filmIor), iorToF0(baseIor.z, filmIor)};
    const Vec3 r23 = fresnelSchlick(r1, cosFilm);
    const Vec3 phi{phi21 + (baseIor.x < filmIor ? kPi : 0.0f), phi21 + (baseIor.y < filmIor ? kPi : 0.0f),
                   phi21 + (baseIor.z < filmIor ? kPi : 0.0f)};
    const float opd = 2.0f * filmIor * film.thickness * cosFilm;
    const Vec3 r123 = vmin(vmax(r23 * r12, Vec3(1e-5f)), Vec3(0.9999f));
    const Vec3 amplitude{sqrtf(r123.x), sqrtf(r123.y), sqrtf(r123.z)};
    const Vec3 rs = r23 * (t121 * t121) / (Vec3(1.0f) - r123);
    Vec3 reflectance = rs + Vec3(r12);  // the order-0 (incoherent) term
    Vec3 cm = rs - Vec3(t121);
    for (int m = 1; m <= 2; ++m) {
        cm = cm * amplitude;
        reflectance += cm * evalSensitivity(float(m) * opd, phi * float(m)) * 2.0f;
    }
    return vmin(vmax(reflectance, Vec3(0.0f)), Vec3(1.0f));
}

// The specular lobe's Fresnel term with a film over its metal and dielectric parts (each with its
// own base): Schlick's F0/F90 term without the film, mixed with the film's reflectance by the
// film's weight, as the extension mixes them.
struct FilmedSpecular {
    ThinFilm film;
    Vec3 metalF0;            // the metal's base (baseColor)
    float metalWeight;       // metallic, times the layers above
    Vec3 dielectricF0;       // the specular layer's base, min(F0(ior) specularColor, 1)
    float dielectricWeight;  // (1 - metallic)(1 - transmission) specular, times the layers above
};
struct IridescentFresnel {
    Vec3 f0, f90;  // the lobe without the film (weights folded in)
    const FilmedSpecular& filmed;
    PT_HD Vec3 operator()(float cosTheta) const {
        const Vec3 plain = fresnelSchlick(f0, f90, cosTheta);
        const ThinFilm& film = filmed.film;
        if (!(film.weight > 0.0f)) return plain;
        Vec3 withFilm(0.0f);
        if (filmed.metalWeight > 0.0f)
            withFilm += thinFilmFresnel(film, filmed.metalF0, cosTheta) * filmed.metalWeight;
        if (filmed.dielectricWeight > 0.0f)
            withFilm += thinFilmFresnel(film, filmed.dielectricF0, cosTheta) * filmed.dielectricWeight;
        return plain * (1.0f - film.weight) + withFilm * film.weight;
    }
};

// The glass lobe's Fresnel term under a film (rough_dielectric.h's Fresnel callable): the exact
// dielectric term mixed with the film's by the film's weight. A film is lossless, so it reflects
// the same from either side at angles Snell's law pairs (Stokes' relations); from inside, the
// film's reflectance is taken at the outside angle, and beyond the critical angle all reflects.
struct FilmedDielectricFresnel {
    const FilmedSpecular& filmed;
    PT_HD Vec3 operator()(float cosTheta, float etap) const {
        const float exact = fresnelDielectric(cosTheta, etap);
        float cosOutside = cosTheta;
        if (etap < 1.0f) {  // from inside
            const float sin2 = (1.0f - cosTheta * cosTheta) / (etap * etap);
            if (sin2 >= 1.0f) return Vec3(1.0f);
            cosOutside = sqrtf(1.0f - sin2);
        }
        const float w = filmed.film.weight;
        return Vec3(exact * (1.0f - w)) + thinFilmFresnel(filmed.film, filmed.dielectricF0, cosOutside) * w;
    }
};

}  // namespace pt
