#pragma once
// The timeline's clock (issue 19): plays the scene's animations at a speed, looping or stopping
// at the end, by wall time, so a slow frame skips animation time rather than slowing it. Each
// new time it gives is an edit (setAnimationTime): accumulation restarts per frame while it
// plays and converges once it is paused.
namespace pt::editor {

class AnimationPlayback {
public:
    bool playing() const { return playing_; }
    void play() { playing_ = true; }
    void pause() { playing_ = false; }

    bool loop = true;
    float speed = 1.0f;  // animation seconds per wall second; negative plays backwards

    // The time to show after `elapsed` wall seconds of playing from `time`, in animations
    // `duration` long: wrapped into [0, duration) when looping, else clamped to the end it
    // ran into, where playback pauses. `time` itself while paused or for no duration.
    float advance(float time, float duration, double elapsed);

private:
    bool playing_ = false;
};

}  // namespace pt::editor
