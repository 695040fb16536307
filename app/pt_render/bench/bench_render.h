#pragma once
// Path tracing figures for `pt-render bench`: samples per pixel per second and Mpaths/s with
// the toggles on and off, and the image check of a GPU backend against the CPU one.
#include <string>

#include "pt_render/bench/bench_report.h"
#include "render/backend/backend.h"

namespace pt::cli {

struct BenchSettings {
    uint32_t runs = 5;
    uint32_t spp = 4;           // per timed path-tracing run
    IntegratorToggles toggles;  // the base every variant flips one toggle of
};

void benchPathTracing(Backend& backend, const Scene& scene, const BenchSettings& settings,
                      BenchReport& report);
// The wavefront's own costs on a GPU backend: the bytes of device memory a path carries between
// stages, and the fixed cost of a bounce (its launches, the queue-size read-back and the host
// sync), timed on a one-pixel image where the work itself is nil.
void benchWavefrontOverhead(Backend& backend, Scene scene, const BenchSettings& settings,
                            BenchReport& report);
// The denoiser (render/denoise/) at the bench's image size: the filter's time alone (on a GPU
// its kernels, without the copy to the host), median of the runs.
void benchDenoise(Backend& backend, const Scene& scene, const BenchSettings& settings, BenchReport& report);
// Renders a reduced-size copy of the scene on `backend` and on the CPU at equal samples.
void benchImageCheck(Backend& backend, Scene scene, const BenchSettings& settings, BenchReport& report);

}  // namespace pt::cli
