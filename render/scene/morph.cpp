#include "render/scene/morph.h"

#include <cmath>
#include <stdexcept>
#include <string>

namespace pt {
namespace {

void checkMorphShape(const Mesh& mesh) {
    const std::string at = "applyMorphWeights: mesh \"" + mesh.name + "\": ";
    if (mesh.morphWeights.size() != mesh.morphTargets.size()) {
        throw std::invalid_argument(at + std::to_string(mesh.morphWeights.size()) + " weights for " +
                                    std::to_string(mesh.morphTargets.size()) + " morph targets");
    }
    const size_t vertices = mesh.basePositions.size();
    if (!mesh.baseNormals.empty() && mesh.baseNormals.size() != vertices) {
        throw std::invalid_argument(at + "baseNormals and basePositions differ in size");
    }
    for (const MorphTarget& target : mesh.morphTargets) {
        if (target.positionDeltas.size() != vertices ||
            (!target.normalDeltas.empty() && target.normalDeltas.size() != vertices)) {
            throw std::invalid_argument(at + "target \"" + target.name +
                                        "\" has a delta count other than the vertex count");
        }
    }
}

void deformNormals(Mesh& mesh) {
    mesh.normals = mesh.baseNormals;
    bool moved = false;
    for (size_t t = 0; t < mesh.morphTargets.size(); ++t) {
        const float w = mesh.morphWeights[t];
        const std::vector<Vec3>& deltas = mesh.morphTargets[t].normalDeltas;
        if (w == 0.0f || deltas.empty()) continue;
        moved = true;
        for (size_t v = 0; v < deltas.size(); ++v) mesh.normals[v] += w * deltas[v];
    }
    // Unmoved normals stay the base ones exactly: renormalizing a unit vector can change its
    // last bit, and weights of zero must restore the file's vertices bit for bit.
    if (!moved) return;
    for (size_t v = 0; v < mesh.normals.size(); ++v) {
        const float len = length(mesh.normals[v]);
        const bool usable = len > 0.0f && std::isfinite(len);
        mesh.normals[v] = usable ? mesh.normals[v] / len : mesh.baseNormals[v];
    }
}

}  // namespace

void applyMorphWeights(Mesh& mesh) {
    if (!hasMorphTargets(mesh)) return;
    checkMorphShape(mesh);
    mesh.positions = mesh.basePositions;
    for (size_t t = 0; t < mesh.morphTargets.size(); ++t) {
        const float w = mesh.morphWeights[t];
        if (w == 0.0f) continue;  // base + 0 x delta could turn a -0 coordinate into +0
        const std::vector<Vec3>& deltas = mesh.morphTargets[t].positionDeltas;
        for (size_t v = 0; v < deltas.size(); ++v) mesh.positions[v] += w * deltas[v];
    }
    if (!mesh.baseNormals.empty()) deformNormals(mesh);
}

bool hasMorphTargets(const Mesh& mesh) { return !mesh.morphTargets.empty(); }

}  // namespace pt
