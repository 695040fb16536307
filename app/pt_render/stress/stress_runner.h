#pragma once
// What a case of the robustness suite can ask for: a scene of scenes/stress/ (or scenes/)
// loaded, edited, and rendered on the backend under test as independent batches at the
// suite's size and sample count, or merely loaded, to see whether and how it is refused.
#include <functional>
#include <map>
#include <string>
#include <vector>

#include "pt_render/batched_render.h"
#include "render/scene/scene.h"

namespace pt::cli {

using SceneEdit = std::function<void(Scene&)>;

// How much to render: --quick (CI) or the full suite.
struct StressBudget {
    uint32_t width = 0, height = 0;
    uint32_t sppPerBatch = 0, batches = 4;
};

enum class StressScale { Box, Furnace, Accumulation };  // Cornell-like, furnace, constant

// The seed of baseline images: far from the seeds cases render with, so the two are independent.
constexpr uint32_t kBaselineSeed = 1000;

class StressRunner {
public:
    StressRunner(std::string backend, bool quick, std::string scenesFolder);

    const std::string& backend() const { return backend_; }
    bool quick() const { return quick_; }
    StressBudget budget(StressScale scale) const;

    // `scene` is relative to scenes/. `seed` selects the batches' seeds, so that an image and
    // its baseline are independent. Throws std::runtime_error with the loader's message.
    BatchedImage render(const std::string& scene, StressScale scale, const SceneEdit& edit = {},
                        uint32_t seed = 0);
    // Renders each (scene, scale, seed) once per suite run; for baselines several cases share.
    const BatchedImage& baseline(const std::string& scene, StressScale scale);
    // The warnings of the last scene loaded by render().
    const std::vector<std::string>& warnings() const { return warnings_; }

    // Loads without rendering: empty when it loaded, else the loader's message.
    std::string loadError(const std::string& scene) const;

private:
    std::string backend_;
    bool quick_;
    std::string scenesFolder_;
    std::vector<std::string> warnings_;
    std::map<std::string, BatchedImage> baselines_;
};

}  // namespace pt::cli
