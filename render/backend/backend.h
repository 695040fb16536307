#pragma once
// Backend: the one interface the CLI and the editor know a renderer by (STYLE.md rule 4).
// A backend owns its copy of the compiled scene and a progressive accumulation of linear
// radiance; sync() brings the copy up to date after an edit, render() adds samples.
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "render/scene/scene.h"
#include "render/scene/scene_changes.h"
#include "render/util/progress.h"

namespace pt {

struct IntegratorToggles {
    bool nextEventEstimation = true;
    bool multipleImportance = true;
    bool russianRoulette = true;
    bool bruteForce = false;  // BVH off: validation only, refused above a triangle budget
    float clampRadiance = 0.0f;  // firefly clamp on indirect luminance per sample; 0 = off
};

struct SyncReport {
    std::string action;        // what sync did, e.g. "compile scene", "materials", "reset"
    double seconds = 0.0;
    double bvhSeconds = 0.0;   // BLAS + TLAS build time within `seconds`
};

struct BackendStats {
    uint32_t samplesPerPixel = 0;
    double renderSeconds = 0.0;   // time spent in render() since the last reset
    uint64_t rays = 0;            // closest-hit and shadow rays since the last reset
    uint64_t nonfiniteSamples = 0;  // NaN/Inf samples dropped since the last reset
    uint64_t triangles = 0;       // traced (over instances)
    uint32_t instances = 0;
};

class Backend {
public:
    virtual ~Backend() = default;
    virtual std::string name() const = 0;

    // Throws std::invalid_argument when the scene or toggles cannot be honoured; the previous
    // state is then kept.
    virtual SyncReport sync(const Scene& scene, SceneChangeMask changes,
                            const ProgressFn& progress = {}) = 0;
    virtual void setToggles(const IntegratorToggles& toggles) = 0;  // takes effect at next sync
    virtual void render(uint32_t passes) = 0;  // adds `passes` samples per pixel
    virtual void resetAccumulation() = 0;

    virtual uint32_t width() const = 0;
    virtual uint32_t height() const = 0;
    // Mean linear radiance, RGBA float (A = 1), row-major, top row first.
    virtual void readBeauty(std::vector<float>& rgba) const = 0;
    virtual BackendStats stats() const = 0;
};

// "cpu", or "cuda" where built. Throws std::invalid_argument naming the backends available.
std::unique_ptr<Backend> createBackend(const std::string& name);

}  // namespace pt
