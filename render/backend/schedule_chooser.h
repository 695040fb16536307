#pragma once
// ScheduleChooser: the "auto" schedule of a GPU backend. Which of the megakernel and the
// wavefront renders a scene faster depends on the scene (measured on an H100 at 1080p: the
// wavefront is twice as fast on the Cornell box, with its glass and mirror, the megakernel
// four times as fast on a textured glTF), so it is measured, not guessed: the first passes
// after the scene, its features or the image size change alternate between the two, each
// pass timed, and the rest run the faster. The trial passes are real samples (both schedules
// render the same image at equal samples), so the trial costs no work, only the slower
// schedule's extra time on a few passes.
// The answer also depends on how many samples a pixel one launch traces (a wave; the CUDA
// backend puts a call's passes in waves of up to 2^23 paths): measured on the H100 at 512x512,
// scenes/instances.json at one sample a wave ran faster on the megakernel, yet at 32 the
// wavefront traced 2.5 times the samples in equal time. So the caller's key includes the wave
// size, trials run whole waves, and each key's decision is kept for when it comes back (the
// editor alternates one-pass steps after edits with longer ones).
#include <cstdint>
#include <string>
#include <unordered_map>

namespace pt {

class ScheduleChooser {
public:
    // Passes of each schedule in a trial; each schedule's fastest counts, so that its first
    // pass's warm-up (buffers, caches) does not decide.
    static constexpr uint32_t kTrialPassesEach = 2;

    // What the decision holds for (features, image size, depth, toggles that change speed,
    // samples a wave); a key not seen before starts a new trial, one seen before has its
    // trial or decision back.
    void setKey(uint64_t key);
    bool decided() const {
        return trial_.megakernelPasses >= kTrialPassesEach && trial_.wavefrontPasses >= kTrialPassesEach;
    }
    // The schedule of the next pass: alternating during the trial, then the faster one.
    bool nextIsMegakernel() const;
    // One timed trial pass (a wave) and the seconds it took per sample a pixel.
    void record(bool megakernel, double secondsPerSample);

    // Samples per pixel per second as measured (0 until the schedule has run a trial pass).
    double megakernelRate() const { return rate(trial_.megakernelSeconds); }
    double wavefrontRate() const { return rate(trial_.wavefrontSeconds); }
    // "megakernel", "wavefront", or "measuring" during the trial.
    std::string choice() const;

private:
    static double rate(double seconds) { return seconds > 0.0 ? 1.0 / seconds : 0.0; }

    struct Trial {
        uint32_t megakernelPasses = 0, wavefrontPasses = 0;
        double megakernelSeconds = 0.0, wavefrontSeconds = 0.0;  // fastest pass of each
    };
    // Trials of keys left, kept up to kKeptKeys (then forgotten all at once: a rare rerun).
    static constexpr size_t kKeptKeys = 64;
    uint64_t key_ = ~uint64_t(0);
    Trial trial_;
    std::unordered_map<uint64_t, Trial> kept_;
};

}  // namespace pt
