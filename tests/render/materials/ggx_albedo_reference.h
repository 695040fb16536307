#pragma once
// Reference single-scattering albedo of the GGX reflection lobe, by deterministic quadrature
// in double precision over the visible-normal sampling domain (independent of the float
// kernel code). Used to generate render/materials/specular_albedo_table.h and to check it.
//
// For Schlick's Fresnel F = F0 + (F90 - F0)(1 - c)^5 the albedo is linear in F0 and F90:
// E(mu) = F0 p(mu) + F90 b(mu), with p = A - B, b = B, A = white albedo, B = albedo of (1 - c)^5.
#include <cmath>

namespace pt::test {

struct AlbedoPair {
    double p, b;
};

// Midpoint rule on n1 x n2 cells of the spherical-cap visible-normal parameterisation; the
// integrand is the sample weight G2 / G1(wo) times the Fresnel polynomial.
inline AlbedoPair ggxAlbedoQuadrature(double mu, double alpha, int n1, int n2) {
    const double pi = 3.14159265358979323846;
    const double wx = std::sqrt(std::fmax(0.0, 1.0 - mu * mu)), wz = mu;
    double vx = alpha * wx, vz = wz;
    const double vl = std::sqrt(vx * vx + vz * vz);
    vx /= vl;
    vz /= vl;
    const double ao = std::sqrt(wz * wz + alpha * alpha * wx * wx);
    double sumA = 0.0, sumB = 0.0;
    for (int i = 0; i < n1; ++i) {
        const double phi = pi * (i + 0.5) / n1;  // [0, pi]: the integrand is mirror symmetric
        const double cp = std::cos(phi), sp = std::sin(phi);
        for (int j = 0; j < n2; ++j) {
            const double u2 = (j + 0.5) / n2;
            const double z = (1.0 - u2) * (1.0 + vz) - vz;
            const double st = std::sqrt(std::fmax(0.0, 1.0 - z * z));
            double mx = alpha * (st * cp + vx), my = alpha * st * sp, mz = std::fmax(z + vz, 0.0);
            const double ml = std::sqrt(mx * mx + my * my + mz * mz);
            if (ml < 1e-300) continue;
            mx /= ml;
            my /= ml;
            mz /= ml;
            const double c = wx * mx + wz * mz;
            if (c <= 0.0) continue;
            const double ix = 2.0 * c * mx - wx, iy = 2.0 * c * my, iz = 2.0 * c * mz - wz;
            if (iz <= 0.0) continue;
            const double ai = std::sqrt(iz * iz + alpha * alpha * (ix * ix + iy * iy));
            const double g = iz * (wz + ao) / (iz * ao + wz * ai);  // G2 / G1(wo)
            const double m = 1.0 - c, m2 = m * m;
            sumA += g;
            sumB += g * m2 * m2 * m;
        }
    }
    const double n = double(n1) * double(n2);
    return {(sumA - sumB) / n, sumB / n};
}

}  // namespace pt::test
