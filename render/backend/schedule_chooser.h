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
// Where the scene has compressed 8-wide BLASes, the trial times each schedule with both walks
// (PassSchedule), and the rest run the fastest of the four.
#include <cstdint>
#include <optional>
#include <string>
#include <unordered_map>

namespace pt {

// How a pass runs: its schedule, and whether its kernels walk the BLASes' compressed 8-wide
// nodes (IntegratorToggles::gpuWideBvh) or their binary ones. Both walks find the same hits, so
// the images are equal; which is faster depends on the schedule and the scene (measured on an
// H200 at 1280x720: the compressed walk traced a 64-instance field 9% faster in the wavefront,
// yet 10% slower in the megakernel, which ran it fastest).
struct PassSchedule {
    bool megakernel = true;
    bool compressedWalk = false;
};

class ScheduleChooser {
public:
    // Passes of each schedule (and walk) in a trial; each one's fastest counts, so that its
    // first pass's warm-up (buffers, caches) does not decide.
    static constexpr uint32_t kTrialPassesEach = 2;

    // What the decision holds for (features, image size, depth, toggles that change speed,
    // samples a wave, whether the scene has compressed nodes); a key not seen before starts a
    // new trial, one seen before has its trial or decision back. `tryCompressedWalk`: the
    // scene has compressed nodes, so the trial times both walks under each schedule.
    void setKey(uint64_t key, bool tryCompressedWalk = false);
    bool decided() const;
    // The next pass: the trial's ways in turn, then the fastest.
    PassSchedule next() const;
    // One timed trial pass (a wave) and the seconds it took per sample a pixel.
    void record(PassSchedule pass, double secondsPerSample);

    // Samples per pixel per second as measured, of each schedule's faster walk (0 until the
    // schedule has run a trial pass).
    double megakernelRate() const;
    double wavefrontRate() const;
    // "megakernel", "wavefront", or "measuring" during the trial.
    std::string choice() const;
    // "compressed" or "binary" once decided where the trial timed both walks; "" otherwise.
    std::string walkChoice() const;

private:
    // The ways a pass can run, in the order a trial tries them: megakernel and wavefront on the
    // binary nodes, then the same on the compressed ones.
    static constexpr uint32_t kWays = 4;
    static uint32_t way(PassSchedule p) { return (p.megakernel ? 0u : 1u) | (p.compressedWalk ? 2u : 0u); }
    static PassSchedule schedule(uint32_t way) { return {(way & 1u) == 0, (way & 2u) != 0}; }
    static double rate(double seconds) { return seconds > 0.0 ? 1.0 / seconds : 0.0; }

    struct Trial {
        uint32_t ways = 2;  // 4 where the compressed walk is tried too
        uint32_t passes[kWays] = {};
        double seconds[kWays] = {};  // fastest pass of each
    };
    // The way tried with the fewest seconds a sample: of all, or of one schedule's two walks;
    // kWays where none has run. Ties go to the first.
    uint32_t fastestWay(std::optional<bool> megakernel = std::nullopt) const;
    double fastestSeconds(bool megakernel) const;

    // Trials of keys left, kept up to kKeptKeys (then forgotten all at once: a rare rerun).
    static constexpr size_t kKeptKeys = 64;
    uint64_t key_ = ~uint64_t(0);
    Trial trial_;
    std::unordered_map<uint64_t, Trial> kept_;
};

}  // namespace pt
