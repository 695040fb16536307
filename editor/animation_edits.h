#pragma once
// Animation as edits (issue 19): which animation each animated file object shows and the time
// into it (SceneObject::animation, animationTime, saved in scene JSON), applied by posing the
// object's rigs, so a new time costs what the pose moved: refits of the skinned and morphed
// meshes' BLASes and a new TLAS, skinned on the GPU where the backend can (Document::skinning).
// Playback and scrubbing are one undo step each while they last (the timeline's drag).
#include <memory>
#include <string>
#include <vector>

#include "editor/edit_command.h"

namespace pt::editor {

// A file object whose rigs have animations.
struct AnimatedObject {
    uint32_t object = 0;
    std::vector<std::string> animations;  // names, in file order
    std::vector<float> durations;         // seconds, parallel
};
std::vector<AnimatedObject> animatedObjects(const Scene& scene);
// The longest animation any animated object shows now (0: none shows one): the timeline's length.
float shownDuration(const Scene& scene);
// The time the animated objects show (they share one), or 0 where none shows an animation.
float shownTime(const Scene& scene);

// Every animated object that shows an animation, at `time` seconds into it (objects at the
// rest pose stay there). Consecutive time commands fold into one undo step.
std::unique_ptr<EditCommand> setAnimationTime(const Document& doc, float time);
// Object `object` shows animation `name` ("": the rest pose) at `time`. Throws
// std::invalid_argument for an object without that animation.
std::unique_ptr<EditCommand> setObjectAnimation(const Document& doc, uint32_t object, const std::string& name,
                                                float time);

}  // namespace pt::editor
