#pragma once
// What `pt-render bench` measures of a GPU backend's BVH builders, behind Backend (issue 16:
// the front end times nothing on the device itself): the device LBVH, PLOC and H-PLOC builds of
// one mesh's triangle boxes and their SAH costs, bottom-up refits of that tree and of the CPU-built tree, and
// the TLAS build over the instances' world boxes.
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

// A clustering build over meshBoxes: its median time, its tree's SAH cost (sah_cost.h).
struct ClusteringBuildFigures {
    double seconds = 0.0;
    float sahCost = 0.0f;
    bool fellBack = false;  // its tree was too deep: an LBVH took its place
};

// Medians over the runs, in seconds of device time.
struct DeviceBvhFigures {
    double buildSeconds = 0.0;  // LBVH over meshBoxes
    float sahCost = 0.0f;       // of that LBVH (sah_cost.h)
    ClusteringBuildFigures ploc, hploc;
    double refitSeconds = 0.0;  // of that LBVH
    double refitCpuTreeSeconds = 0.0;
    double tlasSeconds = 0.0;  // LBVH over instanceBoxes
};

}  // namespace pt
