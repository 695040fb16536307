#pragma once
// Skinning on the GPU (issue 19): a pose left to the device (SkinningSite::Device) uploads the
// mesh's joint matrices, 48 bytes a joint, and one kernel runs the shared per-vertex linear
// blend skinning (render/animation/skin_vertex.h) over its vertices, writing positions,
// normals and tangents where the BLAS refit and the shading read them. A mesh's bind pose and
// joint influences are uploaded on its first pose and kept until the scene is compiled again,
// so a frame of a skinned million-triangle mesh moves its joints over the bus, not its vertices.
#include <cuda_runtime.h>

#include <cstdint>
#include <unordered_map>

#include "render/animation/rig.h"
#include "render/backend/cuda/device_buffer.h"
#include "render/backend/cuda/device_scene.h"

namespace pt::cuda {

class DeviceSkins {
public:
    // Forgets every bind pose (a new compiled scene: the meshes may not be the ones they were).
    void clear() { binds_.clear(); }
    // Skins Scene mesh `mesh` at skinned.pendingJoints into `target` (the mesh's first vertex on
    // the device); its normals and tangents where both the bind pose and the target have them.
    void skin(uint32_t mesh, const SkinnedMesh& skinned, const DeviceScene::VertexArrays& target,
              cudaStream_t stream);
    uint64_t bytes() const;  // bind poses, influences and joint matrices

private:
    struct BindPose {
        DeviceBuffer<Vec3> positions, normals;
        DeviceBuffer<Vec4> tangents;
        DeviceBuffer<JointInfluences> influences;
    };
    const BindPose& bindPose(uint32_t mesh, const SkinnedMesh& skinned, cudaStream_t stream);

    std::unordered_map<uint32_t, BindPose> binds_;  // by Scene mesh
    DeviceBuffer<Affine3> joints_;                  // the pose being skinned
};

}  // namespace pt::cuda
