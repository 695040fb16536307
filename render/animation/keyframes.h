#pragma once
// Keyframe animation as glTF 2.0 defines it (section 3.11 and Appendix C): a sampler holds key
// times and values and interpolates them STEP, LINEAR (spherical for rotations) or
// CUBICSPLINE (cubic Hermite with the file's tangents); a channel points a sampler at one
// node's translation, rotation, scale or morph weights. Host code: the editor and the CLI pose
// the scene at a time, and the backends refit what moved (DESIGN.md, "Data flow").
#include <cstdint>
#include <string>
#include <vector>

#include "render/math/affine.h"
#include "render/math/vec.h"

namespace pt {

enum class Interpolation : uint8_t { Step, Linear, CubicSpline };
enum class AnimatedPath : uint8_t { Translation, Rotation, Scale, Weights };

struct KeyframeSampler {
    Interpolation interpolation = Interpolation::Linear;
    // Floats per value: 3 (translation, scale), 4 (rotation, a quaternion x y z w), or the
    // morph target count (weights).
    uint32_t components = 0;
    std::vector<float> times;  // seconds, strictly increasing
    // Per key `components` floats; CUBICSPLINE keys hold three values each: the in-tangent,
    // the value, the out-tangent (glTF's order).
    std::vector<float> values;
};

// Throws std::invalid_argument saying what is wrong: no keys, times not finite or not
// strictly increasing, a value count that does not match the keys, non-finite values.
void checkKeyframeSampler(const KeyframeSampler& sampler);

// The sampler's value at `time` into out[0, components): before the first key the first
// value, after the last the last (looping is the player's business). `rotation`: the values
// are unit quaternions, interpolated along the shorter arc (slerp) and renormalised.
void sampleKeyframes(const KeyframeSampler& sampler, float time, bool rotation, float* out);

struct AnimationChannel {
    uint32_t sampler = 0;  // Animation::samplers index
    uint32_t node = 0;     // the file's node index
    AnimatedPath path = AnimatedPath::Translation;
};

struct Animation {
    std::string name;
    std::vector<KeyframeSampler> samplers;
    std::vector<AnimationChannel> channels;
    // The last key time over every sampler (0 for none): a loop's length.
    float duration() const;
};

// A node's local transform as glTF gives it, which channels animate.
struct NodePose {
    Vec3 translation{0.0f, 0.0f, 0.0f};
    Vec4 rotation{0.0f, 0.0f, 0.0f, 1.0f};  // unit quaternion x y z w
    Vec3 scale{1.0f, 1.0f, 1.0f};
    std::vector<float> weights;  // morph weights of the node's mesh; empty where none
    // A node given as a matrix (glTF does not animate those): that matrix, TRS unused.
    bool fixed = false;
    Affine3 fixedMatrix;
    Affine3 matrix() const;  // T * R * S, or the fixed matrix
};

// Poses `nodes` (indexed as the channels' nodes) at `time`: each channel overwrites its path
// of its node. Throws std::invalid_argument for a channel naming a missing sampler or node,
// or a weights sampler whose component count differs from the node's weights.
void applyAnimation(const Animation& animation, float time, std::vector<NodePose>& nodes);

}  // namespace pt
