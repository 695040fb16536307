#include "render/backend/cuda/device_skins.h"

namespace pt::cuda {

namespace {

constexpr uint32_t kSkinBlockSize = 256;

struct SkinInputs {
    const Vec3* positions;
    const Vec3* normals;   // null: the target's normals are left as they are
    const Vec4* tangents;  // null: the same for tangents
    const JointInfluences* influences;
    const Affine3* joints;
    uint32_t count;
};

__global__ void skinKernel(SkinInputs in, DeviceScene::VertexArrays out) {
    const uint32_t v = blockIdx.x * blockDim.x + threadIdx.x;
    if (v >= in.count) return;
    const Affine3 m = blendJointMatrices(in.joints, in.influences[v]);
    out.positions[v] = m.transformPoint(in.positions[v]);
    if (in.normals) out.normals[v] = skinNormal(m, in.normals[v]);
    if (in.tangents) out.tangents[v] = skinTangent(m, in.tangents[v]);
}

}  // namespace

const DeviceSkins::BindPose& DeviceSkins::bindPose(uint32_t mesh, const SkinnedMesh& skinned,
                                                   cudaStream_t stream) {
    auto found = binds_.find(mesh);
    if (found != binds_.end() && found->second.positions.size() == skinned.bindPositions.size())
        return found->second;
    BindPose& bind = binds_[mesh];
    bind.positions.upload(skinned.bindPositions, stream);
    bind.normals.upload(skinned.bindNormals, stream);
    bind.tangents.upload(skinned.bindTangents, stream);
    bind.influences.upload(skinned.influences, stream);
    return bind;
}

void DeviceSkins::skin(uint32_t mesh, const SkinnedMesh& skinned, const DeviceScene::VertexArrays& target,
                       cudaStream_t stream) {
    const uint32_t count = uint32_t(skinned.bindPositions.size());
    PT_CHECK(skinned.influences.size() == count && !skinned.pendingJoints.empty());
    const BindPose& bind = bindPose(mesh, skinned, stream);
    joints_.upload(skinned.pendingJoints, stream);
    SkinInputs in{bind.positions.data(), nullptr, nullptr, bind.influences.data(), joints_.data(), count};
    if (target.normals && bind.normals.size() == count) in.normals = bind.normals.data();
    if (target.tangents && bind.tangents.size() == count) in.tangents = bind.tangents.data();
    if (count == 0) return;
    skinKernel<<<(count + kSkinBlockSize - 1) / kSkinBlockSize, kSkinBlockSize, 0, stream>>>(in, target);
    PT_CUDA_CHECK_LAUNCH("skinKernel");
}

uint64_t DeviceSkins::bytes() const {
    uint64_t total = joints_.bytes();
    for (const auto& [mesh, bind] : binds_) {
        total +=
            bind.positions.bytes() + bind.normals.bytes() + bind.tangents.bytes() + bind.influences.bytes();
    }
    return total;
}

}  // namespace pt::cuda
