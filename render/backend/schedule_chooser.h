#pragma once
// ScheduleChooser: the "auto" schedule of a GPU backend. Which of the megakernel and the
// wavefront renders a scene faster depends on the scene (measured on an H100 at 1080p: the
// wavefront is twice as fast on the Cornell box, with its glass and mirror, the megakernel
// four times as fast on a textured glTF), so it is measured, not guessed: the first passes
// after the scene, its features or the image size change alternate between the two, each
// pass timed, and the rest run the faster. The trial passes are real samples (both schedules
// render the same image at equal samples), so the trial costs no work, only the slower
// schedule's extra time on a few passes.
#include <cstdint>
#include <string>

namespace pt {

class ScheduleChooser {
public:
    // Passes of each schedule in a trial; each schedule's fastest counts, so that its first
    // pass's warm-up (buffers, caches) does not decide.
    static constexpr uint32_t kTrialPassesEach = 2;

    // What the decision holds for (features, image size, depth, toggles that change speed);
    // a new key starts a new trial.
    void setKey(uint64_t key);
    bool decided() const {
        return megakernelPasses_ >= kTrialPassesEach && wavefrontPasses_ >= kTrialPassesEach;
    }
    // The schedule of the next pass: alternating during the trial, then the faster one.
    bool nextIsMegakernel() const;
    // One timed pass of one sample per pixel.
    void record(bool megakernel, double seconds);

    // Samples per pixel per second as measured (0 until the schedule has run a trial pass).
    double megakernelRate() const { return rate(megakernelSeconds_); }
    double wavefrontRate() const { return rate(wavefrontSeconds_); }
    // "megakernel", "wavefront", or "measuring" during the trial.
    std::string choice() const;

private:
    static double rate(double seconds) { return seconds > 0.0 ? 1.0 / seconds : 0.0; }

    uint64_t key_ = ~uint64_t(0);
    uint32_t megakernelPasses_ = 0, wavefrontPasses_ = 0;
    double megakernelSeconds_ = 0.0, wavefrontSeconds_ = 0.0;  // fastest pass of each
};

}  // namespace pt
