// Animation: the timeline of the scene's glTF animations (issue 19). Each animated object shows
// one of its animations (or its rest pose); one time drives them all. Play, pause, scrub, loop
// and speed: every new time is an edit that refits the BLASes the pose moved and rebuilds the
// TLAS, so accumulation restarts each frame while playing and converges once paused. The Stats
// panel shows what each frame's sync cost.
#include <algorithm>
#include <string>
#include <vector>

#include "assets/scene_loader.h"
#include "editor/animation_edits.h"
#include "editor/ui/widgets.h"

namespace pt::editor {

namespace {

constexpr float kFramesPerSecond = 30.0f;  // for the frame readout and the step buttons

// Per object: which of its animations it shows.
void animationChoices(EditorUi& ui, const std::vector<AnimatedObject>& animated, float time) {
    for (const AnimatedObject& a : animated) {
        const SceneObject& object = ui.doc().scene.objects[a.object];
        ImGui::PushID(int(a.object));
        const std::string shown = object.animation.empty() ? "(rest pose)" : object.animation;
        const std::string label = objectDisplayName(object);
        if (ImGui::BeginCombo(label.c_str(), shown.c_str())) {
            if (ImGui::Selectable("(rest pose)", object.animation.empty()) && !object.animation.empty())
                ui.apply(setObjectAnimation(ui.doc(), a.object, "", time));
            for (size_t i = 0; i < a.animations.size(); ++i) {
                char item[256];
                std::snprintf(item, sizeof item, "%s (%.2f s)", a.animations[i].c_str(),
                              double(a.durations[i]));
                const bool selected = a.animations[i] == object.animation;
                if (ImGui::Selectable(item, selected) && !selected)
                    ui.apply(setObjectAnimation(ui.doc(), a.object, a.animations[i], time));
            }
            ImGui::EndCombo();
        }
        tooltipIfCut(label.c_str());
        ImGui::PopID();
    }
}

// Play on a scene at rest starts each object's first animation.
void startPlaying(EditorUi& ui, const std::vector<AnimatedObject>& animated, float time) {
    for (const AnimatedObject& a : animated) {
        if (ui.doc().scene.objects[a.object].animation.empty())
            ui.apply(setObjectAnimation(ui.doc(), a.object, a.animations.front(), time));
    }
    ui.playback.play();
}

void transport(EditorUi& ui, const std::vector<AnimatedObject>& animated, float time, float duration) {
    if (ui.playback.playing()) {
        if (ImGui::Button("Pause")) {
            ui.playback.pause();
            ui.endDrag();  // playback was one undo step
        }
    } else if (ImGui::Button("Play")) {
        startPlaying(ui, animated, time);
    }
    const float frame = 1.0f / kFramesPerSecond;
    ImGui::BeginDisabled(duration <= 0.0f || ui.playback.playing());
    const float steps[] = {-time, -frame, frame};  // to the start, a frame back, a frame on
    const char* labels[] = {"|<", "<", ">"};
    for (int i = 0; i < 3; ++i) {
        ImGui::SameLine();
        if (ImGui::Button(labels[i])) {
            ui.apply(setAnimationTime(ui.doc(), std::clamp(time + steps[i], 0.0f, duration)));
            ui.endDrag();  // each step its own undo step
        }
    }
    ImGui::EndDisabled();
    ImGui::SameLine();
    ImGui::Checkbox("Loop", &ui.playback.loop);
    ImGui::SliderFloat("Speed", &ui.playback.speed, -2.0f, 4.0f, "%.2fx");
}

}  // namespace

void drawAnimationPanel(EditorUi& ui) {
    const std::vector<AnimatedObject> animated = animatedObjects(ui.doc().scene);
    if (!ImGui::CollapsingHeader("Animation", animated.empty() ? 0 : ImGuiTreeNodeFlags_DefaultOpen)) return;
    if (animated.empty()) {
        ImGui::TextDisabled("The scene has no animations (glTF skins, node or morph keyframes).");
        return;
    }
    float time = shownTime(ui.doc().scene);
    const float duration = shownDuration(ui.doc().scene);
    animationChoices(ui, animated, time);
    transport(ui, animated, time, duration);
    ImGui::BeginDisabled(duration <= 0.0f);
    // Scrubbing is a drag: one undo step, each position posing the scene.
    if (ImGui::SliderFloat("Time", &time, 0.0f, std::max(duration, 1e-3f), "%.3f s")) {
        ui.playback.pause();
        ui.apply(setAnimationTime(ui.doc(), time));
    }
    closeStepIfReleased(ui);
    ImGui::EndDisabled();
    ImGui::Text("Frame %d at %.0f fps of %.2f s%s", int(time * kFramesPerSecond + 0.5f),
                double(kFramesPerSecond), double(duration),
                ui.doc().skinning == SkinningSite::Device ? ", skinned on the GPU" : "");
    if (duration <= 0.0f)
        ImGui::TextDisabled("Choose an animation above, or press Play for each one's first.");
}

}  // namespace pt::editor
