// Animated frames on the CPU backend refit the skinned mesh's BLAS, or compile again where the
// refit's SAH cost has drifted past IntegratorToggles::rebuildSahRatio times the cost as built:
// the decision follows the ratio a host refit of the same tree predicts, at thresholds on
// either side of each frame's ratio.
#include <gtest/gtest.h>

#include "render/backend/cpu/cpu_backend.h"
#include "support/skinned_grid.h"

namespace pt {
namespace {

TEST(CpuAnimatedRefit, RefitOrRebuildFollowsTheSahRatio) {
    test::expectRefitDecisionsFollowTheSahRatio(60, "full build", [](float threshold, float bend) {
        Scene scene = test::skinnedGridScene(60);
        CpuBackend cpu;
        IntegratorToggles toggles;
        toggles.rebuildSahRatio = threshold;
        cpu.setToggles(toggles);
        cpu.sync(scene, SceneChanges::All, {});
        test::bendSkinnedGrid(scene, bend);
        return cpu.sync(scene, poseRig(scene, 0, -1, 0.0f, SkinningSite::Host), {}).action;
    });
}

}  // namespace
}  // namespace pt
