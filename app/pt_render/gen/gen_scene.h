#pragma once
// What `pt-render gen` writes: one mesh, the nodes that instance it, and a camera and lights
// around them, so the file renders lit and framed when opened on its own.
#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "render/scene/scene.h"

namespace pt::cli {

// A glTF node's TRS with a uniform scale; rotation is a unit quaternion (x, y, z, w).
struct GenNode {
    Vec3 translation{0.0f, 0.0f, 0.0f};
    Vec4 rotation{0.0f, 0.0f, 0.0f, 1.0f};
    float scale = 1.0f;
};

// KHR_lights_punctual directional light; it shines along its node's -Z.
struct GenLight {
    std::string name;
    GenNode node;
    double color[3] = {1.0, 1.0, 1.0};  // linear Rec.709
    double intensity = 1.0;             // lux
};

struct GenCamera {
    GenNode node;  // looks along its -Z, +Y up (glTF)
    double yfovRadians = 0.7853981633974483;
    double znear = 0.01;
};

// A skin over a chain of joints (joint j's parent is joint j - 1; joint 0 is a root) and one
// looping animation that turns joints 1 and up (glTF 2.0 skins and animations).
struct GenSkin {
    std::vector<GenNode> joints;  // rest poses, local to the parent joint
    // Per vertex of the mesh: four joints (JOINTS_0) and their weights (WEIGHTS_0, summing to 1).
    std::vector<std::array<uint16_t, 4>> vertexJoints;
    std::vector<Vec4> vertexWeights;
    std::vector<std::array<float, 16>> inverseBindMatrices;  // per joint, column-major
    std::string animation;
    std::vector<float> keyTimes;                  // seconds, increasing
    std::vector<std::vector<Vec4>> keyRotations;  // per joint from 1 on: a rotation per key time
};

struct GenScene {
    // Positions, unit normals, indices; one default material. Its morph targets, if any, are
    // written with their POSITION deltas, names and weights; positions and normals then hold the
    // undeformed vertices (the weights are zero), as glTF's base attributes do.
    Mesh mesh;
    std::vector<GenNode> instances;  // every instance references `mesh`
    GenCamera camera;
    std::vector<GenLight> lights;
    std::optional<GenSkin> skin;  // deforms `mesh` (then placed by one instance)
};

// The rotation that turns -Z to `forward` with +Y as near `upHint` as it can be.
Vec4 lookRotation(Vec3 forward, Vec3 upHint);

// A 45-degree camera on the side `towardCamera` of a sphere (centre, radius) that fits it whole.
GenCamera frameSphere(Vec3 centre, float radius, Vec3 towardCamera);

// A 45-degree camera on the side `towardCamera` of the box [lo, hi], aimed at its centre and
// as close as it can be with all eight corners in view (square image).
GenCamera frameBox(Vec3 lo, Vec3 hi, Vec3 towardCamera);

// A warm key light from the upper left, across the view so the relief shows, and a dim cool fill
// from the lower right, so no face the camera sees is black.
std::vector<GenLight> defaultLights();

}  // namespace pt::cli
