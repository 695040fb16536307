// glTF 2.0 keyframe samplers against values computed by hand from the specification's
// formulas (Appendix C), and the channels that pose nodes.
#include "render/animation/keyframes.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <stdexcept>

namespace pt {
namespace {

KeyframeSampler scalar(Interpolation interpolation, std::vector<float> times, std::vector<float> values) {
    KeyframeSampler s;
    s.interpolation = interpolation;
    s.components = 1;
    s.times = std::move(times);
    s.values = std::move(values);
    checkKeyframeSampler(s);
    return s;
}

float at(const KeyframeSampler& s, float t) {
    float v = 0.0f;
    sampleKeyframes(s, t, false, &v);
    return v;
}

Vec4 zRotation(float radians) { return {0.0f, 0.0f, std::sin(radians / 2), std::cos(radians / 2)}; }

TEST(Keyframes, StepHoldsEachKeyUntilTheNext) {
    const KeyframeSampler s = scalar(Interpolation::Step, {0, 1, 2}, {0, 10, 20});
    EXPECT_EQ(at(s, -1.0f), 0.0f) << "before the first key: the first value";
    EXPECT_EQ(at(s, 0.5f), 0.0f);
    EXPECT_EQ(at(s, 1.0f), 10.0f) << "a key's own time takes its value";
    EXPECT_EQ(at(s, 1.999f), 10.0f);
    EXPECT_EQ(at(s, 7.0f), 20.0f) << "after the last key: the last value";
}

TEST(Keyframes, LinearInterpolatesEveryComponent) {
    KeyframeSampler s;
    s.components = 3;
    s.times = {1.0f, 3.0f};
    s.values = {0, 0, 0, 4, -8, 2};
    checkKeyframeSampler(s);
    float v[3];
    sampleKeyframes(s, 1.5f, false, v);
    EXPECT_FLOAT_EQ(v[0], 1.0f);
    EXPECT_FLOAT_EQ(v[1], -2.0f);
    EXPECT_FLOAT_EQ(v[2], 0.5f);
    EXPECT_EQ(at(scalar(Interpolation::Linear, {2.0f}, {5.0f}), 9.0f), 5.0f) << "one key: constant";
}

TEST(Keyframes, LinearRotationsFollowTheShorterArc) {
    KeyframeSampler s;
    s.components = 4;
    s.times = {0.0f, 1.0f};
    const Vec4 a = zRotation(0.0f), b = zRotation(float(M_PI) / 2);
    s.values = {a.x, a.y, a.z, a.w, b.x, b.y, b.z, b.w};
    checkKeyframeSampler(s);
    for (const float u : {0.25f, 0.5f, 0.9f}) {
        float q[4];
        sampleKeyframes(s, u, true, q);
        const Vec4 expected = zRotation(u * float(M_PI) / 2);  // slerp: angle linear in time
        EXPECT_NEAR(q[2], expected.z, 1e-6f) << u;
        EXPECT_NEAR(q[3], expected.w, 1e-6f) << u;
        EXPECT_NEAR(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3], 1.0f, 1e-6f);
    }
    // -b is the same rotation: the interpolation must not take the long way round.
    s.values = {a.x, a.y, a.z, a.w, -b.x, -b.y, -b.z, -b.w};
    float q[4];
    sampleKeyframes(s, 0.5f, true, q);
    const Vec4 half = zRotation(float(M_PI) / 4);
    EXPECT_NEAR(std::fabs(q[2]), half.z, 1e-6f);
    EXPECT_NEAR(std::fabs(q[3]), half.w, 1e-6f);
    EXPECT_GT(q[2] * q[3], 0.0f) << "a rotation about +z by 45 degrees, not 315";
}

TEST(Keyframes, CubicSplineIsTheSpecificationsHermiteCurve) {
    // Keys at t = 0 and 2 with values 1 and 3, key 0's out-tangent 2, key 1's in-tangent -1.
    // At t = 0.5: u = 0.25, dt = 2, h00 = 0.84375, h10 = 0.140625, h01 = 0.15625,
    // h11 = -0.046875; p = 0.84375 + 2(0.140625)(2) + 0.15625(3) + 2(-0.046875)(-1) = 1.96875.
    const KeyframeSampler s = scalar(Interpolation::CubicSpline, {0, 2}, {/*in*/ 7, 1, /*out*/ 2, -1, 3, 9});
    EXPECT_FLOAT_EQ(at(s, 0.5f), 1.96875f);
    EXPECT_FLOAT_EQ(at(s, 0.0f), 1.0f) << "keys are passed through";
    EXPECT_FLOAT_EQ(at(s, 2.0f), 3.0f);
    // Zero tangents: smoothstep between the keys, the midpoint halfway.
    const KeyframeSampler flat = scalar(Interpolation::CubicSpline, {0, 1}, {0, 0, 0, 0, 1, 0});
    EXPECT_FLOAT_EQ(at(flat, 0.5f), 0.5f);
    EXPECT_FLOAT_EQ(at(flat, 0.25f), 0.15625f);  // 3u^2 - 2u^3
}

TEST(Keyframes, CubicSplineRotationsAreRenormalised) {
    KeyframeSampler s;
    s.interpolation = Interpolation::CubicSpline;
    s.components = 4;
    s.times = {0.0f, 1.0f};
    const Vec4 a = zRotation(0.0f), b = zRotation(float(M_PI) / 2);
    s.values = {0, 0, 0, 0, a.x, a.y, a.z, a.w, 0, 0, 0, 0, 0, 0, 0, 0, b.x, b.y, b.z, b.w, 0, 0, 0, 0};
    checkKeyframeSampler(s);
    float q[4];
    sampleKeyframes(s, 0.5f, true, q);
    EXPECT_NEAR(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3], 1.0f, 1e-6f);
    EXPECT_NEAR(q[2], zRotation(float(M_PI) / 4).z, 1e-6f) << "symmetric keys: halfway is 45 degrees";
}

TEST(Keyframes, BadSamplersAreRefusedWithAReason) {
    const auto refused = [](KeyframeSampler s, const char* words) {
        try {
            checkKeyframeSampler(s);
        } catch (const std::invalid_argument& e) {
            EXPECT_NE(std::string(e.what()).find(words), std::string::npos) << e.what();
            return;
        }
        ADD_FAILURE() << "accepted; expected: " << words;
    };
    KeyframeSampler s;
    s.components = 1;
    refused(s, "no keys");
    s.times = {0, 1, 1};
    s.values = {0, 1, 2};
    refused(s, "strictly increasing");
    s.times = {0, 1, 2};
    s.values = {0, 1};
    refused(s, "need 3 output values");
    s.values = {0, std::numeric_limits<float>::quiet_NaN(), 2};
    refused(s, "not finite");
    s.interpolation = Interpolation::CubicSpline;
    s.values = {0, 1, 2};
    refused(s, "need 9 output values");
}

TEST(Keyframes, ChannelsPoseTheirNodesPaths) {
    Animation walk;
    walk.name = "walk";
    KeyframeSampler move;
    move.components = 3;
    move.times = {0, 2};
    move.values = {0, 0, 0, 2, 0, 0};
    KeyframeSampler turn;
    turn.components = 4;
    turn.interpolation = Interpolation::Step;
    turn.times = {0, 1};
    const Vec4 q = zRotation(1.0f);
    turn.values = {0, 0, 0, 1, q.x, q.y, q.z, q.w};
    KeyframeSampler weights;
    weights.components = 2;
    weights.times = {0, 1};
    weights.values = {0, 1, 1, 0};
    walk.samplers = {move, turn, weights};
    walk.channels = {
        {0, 1, AnimatedPath::Translation}, {1, 0, AnimatedPath::Rotation}, {2, 1, AnimatedPath::Weights}};
    std::vector<NodePose> nodes(2);
    nodes[1].weights = {0.0f, 0.0f};
    nodes[1].scale = {2.0f, 2.0f, 2.0f};
    applyAnimation(walk, 1.5f, nodes);
    EXPECT_FLOAT_EQ(nodes[1].translation.x, 1.5f);
    EXPECT_FLOAT_EQ(nodes[1].scale.x, 2.0f) << "paths without a channel keep their pose";
    EXPECT_FLOAT_EQ(nodes[0].rotation.z, q.z);
    EXPECT_FLOAT_EQ(nodes[1].weights[0], 1.0f);
    EXPECT_FLOAT_EQ(nodes[1].weights[1], 0.0f);
    EXPECT_FLOAT_EQ(walk.duration(), 2.0f);
    // T * R * S: a point on x scaled by 2, then moved by 1.5.
    EXPECT_FLOAT_EQ(nodes[1].matrix().transformPoint({1, 0, 0}).x, 3.5f);

    nodes[1].weights = {0.0f};  // the mesh has one target, the channel two
    EXPECT_THROW(applyAnimation(walk, 0.0f, nodes), std::invalid_argument);
    walk.channels = {{5, 0, AnimatedPath::Scale}};
    EXPECT_THROW(applyAnimation(walk, 0.0f, nodes), std::invalid_argument);
}

}  // namespace
}  // namespace pt
