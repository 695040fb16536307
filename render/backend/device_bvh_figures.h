#pragma once
// What `pt-render bench` measures of a GPU backend's BVH builders, behind Backend (issue 16:
// the front end times nothing on the device itself): the device LBVH, PLOC and H-PLOC builds of
// one mesh's triangle boxes and their SAH costs (each also with the leaf collapse after it), bottom-up refits
// of that tree and of the CPU-built tree, and the TLAS build over the instances' world boxes.
#include <cstdint>
#include <vector>

#include "render/bvh/aabb.h"
#include "render/bvh/binned_sah_builder.h"

namespace pt {

struct BvhBuildInput {
    std::vector<Aabb> meshBoxes;      // the largest triangle mesh's triangles, object space
    Bvh cpuTree;                      // the binned SAH tree over meshBoxes
    std::vector<Aabb> instanceBoxes;  // world space
};

// A device build over meshBoxes: its median time and its tree's SAH cost (sah_cost.h), as the
// builder leaves it (one primitive a leaf) and with the leaf collapse after it.
struct GpuBuildFigures {
    double seconds = 0.0;
    float sahCost = 0.0f;
    double collapsedSeconds = 0.0;  // the build and BvhLeafCollapse, as the backend runs them
    float collapsedSahCost = 0.0f;
    uint32_t collapsedNodes = 0;  // the collapsed tree's node count
    bool fellBack = false;        // PLOC, H-PLOC: its tree was too deep and an LBVH took its place
};

// Medians over the runs, in seconds of device time.
struct DeviceBvhFigures {
    GpuBuildFigures lbvh, ploc, hploc;
    double refitSeconds = 0.0;  // of H-PLOC's tree after the leaf collapse
    double refitCpuTreeSeconds = 0.0;
    double tlasSeconds = 0.0;  // LBVH over instanceBoxes
};

}  // namespace pt
