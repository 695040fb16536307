#include "editor/animation_edits.h"

#include <algorithm>
#include <cstdio>
#include <stdexcept>

#include "assets/scene_loader.h"
#include "render/scene/scene_animation.h"

namespace pt::editor {

namespace {

struct ObjectPose {
    uint32_t object = 0;
    std::string animation;  // "": the rest pose
    float time = 0.0f;
};

int32_t animationIndex(const AnimationRig& rig, const std::string& name) {
    for (size_t a = 0; a < rig.animations.size(); ++a) {
        if (rig.animations[a].name == name) return int32_t(a);
    }
    return -1;
}

// Shows each object as `poses` say and poses its rigs; what moved.
SceneDelta applyPoses(Document& doc, const std::vector<ObjectPose>& poses) {
    SceneDelta delta;
    for (const ObjectPose& pose : poses) {
        if (pose.object >= doc.scene.objects.size()) continue;
        SceneObject& object = doc.scene.objects[pose.object];
        object.animation = pose.animation;
        object.animationTime = pose.time;
        for (size_t r = 0; r < doc.scene.rigs.size(); ++r) {
            const AnimationRig& rig = doc.scene.rigs[r];
            if (rig.object != int32_t(pose.object)) continue;
            delta |=
                poseRig(doc.scene, uint32_t(r), animationIndex(rig, pose.animation), pose.time, doc.skinning);
        }
    }
    return delta;
}

std::vector<ObjectPose> posesOf(const Scene& scene, const std::vector<AnimatedObject>& objects) {
    std::vector<ObjectPose> poses;
    for (const AnimatedObject& a : objects) {
        const SceneObject& object = scene.objects[a.object];
        poses.push_back({a.object, object.animation, object.animationTime});
    }
    return poses;
}

class PoseCommand final : public EditCommand {
public:
    PoseCommand(std::string label, std::string mergeKey, std::vector<ObjectPose> before,
                std::vector<ObjectPose> after)
        : label_(std::move(label)),
          mergeKey_(std::move(mergeKey)),
          before_(std::move(before)),
          after_(std::move(after)) {}
    std::string label() const override { return label_; }
    std::string mergeKey() const override { return mergeKey_; }
    SceneDelta apply(Document& doc) override { return applyPoses(doc, after_); }
    SceneDelta revert(Document& doc) override { return applyPoses(doc, before_); }
    void mergeFrom(EditCommand& later) override { after_ = static_cast<PoseCommand&>(later).after_; }

private:
    std::string label_, mergeKey_;
    std::vector<ObjectPose> before_, after_;
};

}  // namespace

std::vector<AnimatedObject> animatedObjects(const Scene& scene) {
    std::vector<AnimatedObject> animated;
    for (const AnimationRig& rig : scene.rigs) {
        if (rig.animations.empty() || rig.object < 0 || size_t(rig.object) >= scene.objects.size()) continue;
        const auto known = std::find_if(animated.begin(), animated.end(), [&](const AnimatedObject& a) {
            return a.object == uint32_t(rig.object);
        });
        AnimatedObject& entry = known != animated.end() ? *known : animated.emplace_back();
        entry.object = uint32_t(rig.object);
        for (const Animation& animation : rig.animations) {
            if (std::find(entry.animations.begin(), entry.animations.end(), animation.name) !=
                entry.animations.end())
                continue;
            entry.animations.push_back(animation.name);
            entry.durations.push_back(animation.duration());
        }
    }
    return animated;
}

float shownDuration(const Scene& scene) {
    float longest = 0.0f;
    for (const AnimatedObject& a : animatedObjects(scene)) {
        const std::string& shown = scene.objects[a.object].animation;
        for (size_t i = 0; i < a.animations.size(); ++i) {
            if (a.animations[i] == shown) longest = std::max(longest, a.durations[i]);
        }
    }
    return longest;
}

float shownTime(const Scene& scene) {
    for (const AnimatedObject& a : animatedObjects(scene)) {
        if (!scene.objects[a.object].animation.empty()) return scene.objects[a.object].animationTime;
    }
    return 0.0f;
}

std::unique_ptr<EditCommand> setAnimationTime(const Document& doc, float time) {
    std::vector<ObjectPose> before;
    for (const ObjectPose& pose : posesOf(doc.scene, animatedObjects(doc.scene))) {
        if (!pose.animation.empty()) before.push_back(pose);
    }
    std::vector<ObjectPose> after = before;
    for (ObjectPose& pose : after) pose.time = time;
    char label[48];
    std::snprintf(label, sizeof label, "Animation time %.2f s", double(time));
    return std::make_unique<PoseCommand>(label, "animation time", before, after);
}

std::unique_ptr<EditCommand> setObjectAnimation(const Document& doc, uint32_t object, const std::string& name,
                                                float time) {
    const std::vector<AnimatedObject> animated = animatedObjects(doc.scene);
    const auto found = std::find_if(animated.begin(), animated.end(),
                                    [&](const AnimatedObject& a) { return a.object == object; });
    if (found == animated.end())
        throw std::invalid_argument("object " + std::to_string(object) + " has no animations");
    if (!name.empty() &&
        std::find(found->animations.begin(), found->animations.end(), name) == found->animations.end())
        throw std::invalid_argument(objectDisplayName(doc.scene.objects[object]) + " has no animation \"" +
                                    name + "\"");
    const SceneObject& o = doc.scene.objects[object];
    return std::make_unique<PoseCommand>(name.empty() ? "Rest pose of " + objectDisplayName(o)
                                                      : "Animation " + name + " of " + objectDisplayName(o),
                                         "", std::vector<ObjectPose>{{object, o.animation, o.animationTime}},
                                         std::vector<ObjectPose>{{object, name, time}});
}

}  // namespace pt::editor
