#pragma once
// AgX-style view transform (Troy Sobotka's AgX as in Blender 4; this is the published
// approximation of Benjamin Wrensch, used by Filament and three.js, "AgXToneMapping"):
//   linear Rec.709 -> linear Rec.2020 -> AgX inset matrix -> log2 encoding over
//   [kAgxMinEv, kAgxMaxEv] stops (0.18 x 2^-10 .. 0.18 x 2^6.5) clamped to [0, 1] -> sigmoid
//   (a polynomial fit of AgX's default contrast curve) -> outset matrix -> power 2.2 (the curve
//   output is display-encoded for a 2.2 display) -> linear Rec.709, clamped to [0, 1].
// The shipped OpenColorIO config's "AgX" view is the same chain built from Matrix, Allocation
// and Exponent transforms plus a 1D LUT of agxSigmoid() (scenes/ocio/luts/agx_sigmoid.spi1d,
// written by assets/color_agx_lut.h); the built-in operator below and that view must agree.
#include "render/math/hd.h"
#include "render/math/vec.h"

namespace pt {

constexpr float kAgxMinEv = -12.47393f;  // log2(0.18 * 2^-10)
constexpr float kAgxMaxEv = 4.026069f;   // log2(0.18 * 2^6.5)

// AgX's default contrast curve on the log-encoded value x in [0, 1] (Wrensch's 6th-order
// polynomial, mean squared error 3.67e-6 against the Blender curve). Display-encoded output,
// slightly below 0 at x = 0 (-0.00232) and about 1 at x = 1.
PT_HD float agxSigmoid(float x) {
    const float x2 = x * x;
    const float x4 = x2 * x2;
    return 15.5f * x4 * x2 - 40.14f * x4 * x + 31.96f * x4 - 6.868f * x2 * x + 0.4298f * x2 + 0.1191f * x -
           0.00232f;
}

PT_HD Vec3 agxMultiply(const float (&m)[3][3], Vec3 v) {
    return Vec3(m[0][0] * v.x + m[0][1] * v.y + m[0][2] * v.z, m[1][0] * v.x + m[1][1] * v.y + m[1][2] * v.z,
                m[2][0] * v.x + m[2][1] * v.y + m[2][2] * v.z);
}

// Linear Rec.709 scene radiance -> linear Rec.709 display light in [0, 1] (encode it with the
// display's curve, e.g. linearToSrgb).
PT_HD Vec3 agxToneMap(Vec3 linear) {
    // Row-major (out_i = sum_j m[i][j] in_j); local so that device code can use them.
    // Rec.709 <-> Rec.2020 from the primaries and D65 (ITU-R BT.709, BT.2020); inset and outset
    // are AgX's (three.js's mat3 columns written as rows: each row sums to 1, so neutrals stay
    // neutral). scenes/ocio/config.ocio's AgX view holds the same numbers.
    const float rec709ToRec2020[3][3] = {{0.627403896f, 0.329283038f, 0.043313066f},
                                         {0.069097289f, 0.919540395f, 0.011362316f},
                                         {0.016391439f, 0.088013308f, 0.895595253f}};
    const float rec2020ToRec709[3][3] = {{1.660491002f, -0.587641139f, -0.072849863f},
                                         {-0.124550475f, 1.132899897f, -0.008349423f},
                                         {-0.018150763f, -0.100578898f, 1.118729661f}};
    const float inset[3][3] = {{0.856627153f, 0.095121241f, 0.048251606f},
                               {0.137318973f, 0.761241991f, 0.101439036f},
                               {0.111898213f, 0.076799419f, 0.811302368f}};
    const float outset[3][3] = {{1.127100582f, -0.110606643f, -0.016493939f},
                                {-0.141329763f, 1.157823702f, -0.016493939f},
                                {-0.141329763f, -0.110606643f, 1.251936407f}};
    Vec3 c = agxMultiply(inset, agxMultiply(rec709ToRec2020, linear));
    for (int i = 0; i < 3; ++i) {
        const float ev = log2f(fmaxf(c[i], 1e-10f));
        const float x = fminf(fmaxf((ev - kAgxMinEv) / (kAgxMaxEv - kAgxMinEv), 0.0f), 1.0f);
        c[i] = agxSigmoid(x);
    }
    c = agxMultiply(outset, c);
    for (int i = 0; i < 3; ++i) c[i] = powf(fmaxf(c[i], 0.0f), 2.2f);
    c = agxMultiply(rec2020ToRec709, c);
    for (int i = 0; i < 3; ++i) c[i] = fminf(fmaxf(c[i], 0.0f), 1.0f);
    return c;
}

}  // namespace pt
