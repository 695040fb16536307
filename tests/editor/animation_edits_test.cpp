// The editor's timeline (issue 19): animation choices and times as undoable edits that pose the
// rigs, playback and scrubbing folded into one undo step, the playback clock, and a session
// whose backend reads the host's vertices catching up a pose left to a device.
#include "editor/animation_edits.h"

#include <gtest/gtest.h>

#include "editor/animation_playback.h"
#include "editor/editor_session.h"
#include "render/scene/scene_animation.h"
#include "support/load_scene.h"
#include "support/test_paths.h"

namespace pt::editor {
namespace {

// skin_lift.gltf: a quad at y in [0, 1], every vertex half on joint 0 (at the origin) and half
// on joint 1, which "lift" raises from y = 1 at 0 s to y = 2 at 1 s: the quad stands
// (1 + t) / 2 above where it was modelled.
Document liftDocument() {
    Document doc;
    doc.scene = test::loadSceneOrFail(test::testDataPath("gltf/skin_lift.gltf"));
    return doc;
}

const Mesh& liftedMesh(const Scene& scene) { return scene.meshes[scene.rigs.at(0).skinnedMeshes.at(0).mesh]; }

// How far the quad's first vertex (modelled at y = 0) stands above where it was modelled.
float lift(const Scene& scene) { return liftedMesh(scene).positions.at(0).y; }

TEST(AnimationEdits, TheTimelineListsTheAnimatedObjects) {
    const Document doc = liftDocument();
    const std::vector<AnimatedObject> animated = animatedObjects(doc.scene);
    ASSERT_EQ(animated.size(), 1u);
    EXPECT_EQ(animated[0].animations, std::vector<std::string>{"lift"});
    EXPECT_EQ(animated[0].durations, std::vector<float>{1.0f});
    EXPECT_EQ(shownDuration(doc.scene), 0.0f) << "at rest, no animation is shown";
    EXPECT_THROW(setObjectAnimation(doc, 0, "walk", 0.0f), std::invalid_argument);
}

TEST(AnimationEdits, ChoosingAnAnimationPosesItAndUndoRestoresTheRestPose) {
    Document doc = liftDocument();
    EXPECT_NEAR(lift(doc.scene), 0.5f, 1e-6f);
    std::unique_ptr<EditCommand> choose = setObjectAnimation(doc, 0, "lift", 0.5f);
    const SceneDelta delta = choose->apply(doc);
    EXPECT_TRUE(delta.has(SceneChanges::Geometry));
    EXPECT_EQ(delta.meshes, TouchedIds::only({doc.scene.rigs[0].skinnedMeshes[0].mesh}));
    EXPECT_EQ(doc.scene.objects[0].animation, "lift");
    EXPECT_EQ(doc.scene.objects[0].animationTime, 0.5f);
    EXPECT_NEAR(lift(doc.scene), 0.75f, 1e-6f);
    EXPECT_EQ(shownDuration(doc.scene), 1.0f);
    choose->revert(doc);
    EXPECT_EQ(doc.scene.objects[0].animation, "");
    EXPECT_NEAR(lift(doc.scene), 0.5f, 1e-6f);
}

TEST(AnimationEdits, PlaybackFramesFoldIntoOneUndoStep) {
    EditorSession session(createBackend("cpu"));
    session.adopt(liftDocument().scene);
    session.execute(setObjectAnimation(session.document(), 0, "lift", 0.0f));
    session.endDrag();
    for (const float t : {0.25f, 0.5f, 0.75f}) session.execute(setAnimationTime(session.document(), t));
    session.endDrag();
    EXPECT_NEAR(lift(session.document().scene), 0.875f, 1e-6f);
    ASSERT_TRUE(session.undo());
    EXPECT_EQ(session.document().scene.objects[0].animationTime, 0.0f)
        << "one undo takes back the whole playback";
    EXPECT_NEAR(lift(session.document().scene), 0.5f, 1e-6f);
    ASSERT_TRUE(session.undo());
    EXPECT_EQ(session.document().scene.objects[0].animation, "");
    EXPECT_FALSE(session.undo());
}

// A pose left to a device (the CUDA backend skins it) leaves the host's vertices behind; a
// backend that reads them must not start from there.
TEST(AnimationEdits, ASessionCatchesUpADevicePoseForAHostBackend) {
    Document doc = liftDocument();
    doc.skinning = SkinningSite::Device;
    setObjectAnimation(doc, 0, "lift", 1.0f)->apply(doc);
    EXPECT_NEAR(lift(doc.scene), 0.5f, 1e-6f) << "the host's vertices wait for the device";
    ASSERT_NE(pendingSkinOf(doc.scene, doc.scene.rigs[0].skinnedMeshes[0].mesh), nullptr);
    EditorSession session(createBackend("cpu"));
    EXPECT_EQ(session.document().skinning, SkinningSite::Host);
    session.adopt(doc.scene);
    session.setBackend(createBackend("cpu"));
    EXPECT_NEAR(lift(session.document().scene), 1.0f, 1e-6f);
    session.sync();
}

TEST(AnimationPlayback, LoopsWrapAndOneShotsStopAtTheEnd) {
    AnimationPlayback playback;
    EXPECT_EQ(playback.advance(0.5f, 2.0f, 1.0), 0.5f) << "paused";
    playback.play();
    EXPECT_FLOAT_EQ(playback.advance(0.5f, 2.0f, 1.0), 1.5f);
    EXPECT_FLOAT_EQ(playback.advance(1.5f, 2.0f, 1.0), 0.5f) << "wrapped";
    playback.speed = -1.0f;
    EXPECT_FLOAT_EQ(playback.advance(0.25f, 2.0f, 0.5), 1.75f) << "backwards, wrapped";
    playback.speed = 2.0f;
    playback.loop = false;
    EXPECT_FLOAT_EQ(playback.advance(0.5f, 2.0f, 0.25), 1.0f);
    EXPECT_TRUE(playback.playing());
    EXPECT_EQ(playback.advance(1.5f, 2.0f, 1.0), 2.0f);
    EXPECT_FALSE(playback.playing()) << "a one-shot pauses at its end";
    playback.play();
    EXPECT_EQ(playback.advance(1.0f, 0.0f, 1.0), 1.0f) << "nothing to play";
}

}  // namespace
}  // namespace pt::editor
