#include "render/animation/keyframes.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace pt {
namespace {

uint32_t valuesPerKey(const KeyframeSampler& s) {
    return s.interpolation == Interpolation::CubicSpline ? 3u * s.components : s.components;
}

// The value of key k (its middle element for CUBICSPLINE).
const float* keyValue(const KeyframeSampler& s, size_t k) {
    const size_t offset = s.interpolation == Interpolation::CubicSpline ? s.components : 0;
    return s.values.data() + k * valuesPerKey(s) + offset;
}

void normalizeQuaternion(float* q) {
    const float length = std::sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
    if (!(length > 0.0f)) {
        q[0] = q[1] = q[2] = 0.0f;
        q[3] = 1.0f;
        return;
    }
    for (int i = 0; i < 4; ++i) q[i] /= length;
}

// Spherical linear interpolation along the shorter arc (Shoemake 1985), falling back to a
// normalised lerp where the two are nearly parallel and sin(angle) loses its precision.
// The keys are normalised first: files round their quaternions, and the angle between two
// keys is only right for unit ones.
void slerp(const float* keyA, const float* keyB, float s, float* out) {
    float a[4], b[4];
    std::copy(keyA, keyA + 4, a);
    std::copy(keyB, keyB + 4, b);
    normalizeQuaternion(a);
    normalizeQuaternion(b);
    float cosAngle = a[0] * b[0] + a[1] * b[1] + a[2] * b[2] + a[3] * b[3];
    const float sign = cosAngle < 0.0f ? -1.0f : 1.0f;
    cosAngle *= sign;
    float wa = 1.0f - s, wb = s;
    if (cosAngle < 0.9995f) {
        const float angle = std::acos(cosAngle);
        const float sinAngle = std::sin(angle);
        wa = std::sin((1.0f - s) * angle) / sinAngle;
        wb = std::sin(s * angle) / sinAngle;
    }
    for (int i = 0; i < 4; ++i) out[i] = wa * a[i] + sign * wb * b[i];
    normalizeQuaternion(out);
}

}  // namespace

void checkKeyframeSampler(const KeyframeSampler& s) {
    if (s.times.empty()) throw std::invalid_argument("the sampler has no keys");
    if (s.components == 0) throw std::invalid_argument("the sampler's values have no components");
    for (size_t k = 0; k < s.times.size(); ++k) {
        if (!std::isfinite(s.times[k])) {
            throw std::invalid_argument("key " + std::to_string(k) + "'s time is not finite");
        }
        if (k > 0 && !(s.times[k] > s.times[k - 1])) {
            throw std::invalid_argument("key times are not strictly increasing at key " + std::to_string(k));
        }
    }
    const size_t expected = s.times.size() * valuesPerKey(s);
    if (s.values.size() != expected) {
        throw std::invalid_argument(std::to_string(s.times.size()) + " keys need " +
                                    std::to_string(expected) + " output values, the sampler has " +
                                    std::to_string(s.values.size()));
    }
    for (size_t i = 0; i < s.values.size(); ++i) {
        if (!std::isfinite(s.values[i])) {
            throw std::invalid_argument("output value " + std::to_string(i) + " is not finite");
        }
    }
}

void sampleKeyframes(const KeyframeSampler& s, float time, bool rotation, float* out) {
    const uint32_t n = s.components;
    const size_t keys = s.times.size();
    // The key interval [k, k + 1] holding `time`, clamped to the ends.
    if (keys == 1 || !(time > s.times.front()) || time >= s.times.back()) {
        const float* v = keyValue(s, keys == 1 || !(time > s.times.front()) ? 0 : keys - 1);
        std::copy(v, v + n, out);
        if (rotation) normalizeQuaternion(out);
        return;
    }
    const size_t k = size_t(std::upper_bound(s.times.begin(), s.times.end(), time) - s.times.begin()) - 1;
    const float t0 = s.times[k], dt = s.times[k + 1] - t0;
    const float u = (time - t0) / dt;
    const float* a = keyValue(s, k);
    const float* b = keyValue(s, k + 1);
    switch (s.interpolation) {
        case Interpolation::Step: std::copy(a, a + n, out); break;
        case Interpolation::Linear:
            if (rotation) {
                slerp(a, b, u, out);
                return;
            }
            for (uint32_t i = 0; i < n; ++i) out[i] = a[i] + u * (b[i] - a[i]);
            break;
        case Interpolation::CubicSpline: {
            // glTF 2.0 Appendix C: p(u) = (2u^3 - 3u^2 + 1) v_k + dt (u^3 - 2u^2 + u) b_k
            //                            + (-2u^3 + 3u^2) v_k+1 + dt (u^3 - u^2) a_k+1,
            // with b_k key k's out-tangent and a_k+1 key k + 1's in-tangent.
            const float u2 = u * u, u3 = u2 * u;
            const float* outTangent = a + n;
            const float* inTangent = b - n;
            for (uint32_t i = 0; i < n; ++i) {
                out[i] = (2 * u3 - 3 * u2 + 1) * a[i] + dt * (u3 - 2 * u2 + u) * outTangent[i] +
                         (-2 * u3 + 3 * u2) * b[i] + dt * (u3 - u2) * inTangent[i];
            }
            break;
        }
    }
    if (rotation) normalizeQuaternion(out);
}

float Animation::duration() const {
    float last = 0.0f;
    for (const KeyframeSampler& s : samplers) {
        if (!s.times.empty()) last = std::max(last, s.times.back());
    }
    return last;
}

Affine3 NodePose::matrix() const {
    if (fixed) return fixedMatrix;
    return translationTransform(translation) * rotationTransform(rotation) * scaleTransform(scale);
}

void applyAnimation(const Animation& animation, float time, std::vector<NodePose>& nodes) {
    for (const AnimationChannel& c : animation.channels) {
        if (c.sampler >= animation.samplers.size() || c.node >= nodes.size()) {
            throw std::invalid_argument("animation \"" + animation.name + "\": a channel names sampler " +
                                        std::to_string(c.sampler) + " of node " + std::to_string(c.node) +
                                        ", which does not exist");
        }
        const KeyframeSampler& s = animation.samplers[c.sampler];
        NodePose& node = nodes[c.node];
        const uint32_t expected = c.path == AnimatedPath::Rotation  ? 4u
                                  : c.path == AnimatedPath::Weights ? uint32_t(node.weights.size())
                                                                    : 3u;
        if (s.components != expected) {
            throw std::invalid_argument("animation \"" + animation.name + "\": node " +
                                        std::to_string(c.node) + "'s channel has " +
                                        std::to_string(s.components) + " components a key, its path needs " +
                                        std::to_string(expected));
        }
        if (c.path == AnimatedPath::Weights) {
            sampleKeyframes(s, time, false, node.weights.data());
            continue;
        }
        float v[4];
        sampleKeyframes(s, time, c.path == AnimatedPath::Rotation, v);
        switch (c.path) {
            case AnimatedPath::Translation: node.translation = {v[0], v[1], v[2]}; break;
            case AnimatedPath::Rotation: node.rotation = {v[0], v[1], v[2], v[3]}; break;
            case AnimatedPath::Scale: node.scale = {v[0], v[1], v[2]}; break;
            case AnimatedPath::Weights: break;
        }
    }
}

}  // namespace pt
