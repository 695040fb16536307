// SceneDelta (issue 16): the session merges the deltas of the edits since the last sync, and
// the merge keeps every id a backend must update: a bit that one edit names with ids and
// another with none means every item of that kind.
#include "render/scene/scene_changes.h"

#include <gtest/gtest.h>

#include "support/scene_delta_print.h"

namespace pt {
namespace {

TEST(SceneDelta, AMaskNamesEveryItemOfItsKinds) {
    const SceneDelta delta = SceneChanges::Materials | SceneChanges::Camera;
    EXPECT_TRUE(delta.has(SceneChanges::Materials));
    EXPECT_TRUE(delta.materials.every);
    EXPECT_TRUE(delta.materials.contains(12345));
}

TEST(SceneDelta, MergingUnitesTheIdsOfEachKind) {
    SceneDelta delta = materialsEdited({3, 1});
    EXPECT_EQ(delta.materials.ids, (std::vector<uint32_t>{1, 3})) << "sorted";
    delta |= materialsEdited({2, 3});
    EXPECT_EQ(delta, materialsEdited({1, 2, 3}));
    EXPECT_FALSE(delta.materials.contains(0));
    delta |= meshesMoved({7});
    EXPECT_EQ(delta.mask, SceneChanges::Materials | SceneChanges::Geometry);
    EXPECT_EQ(delta.meshes, TouchedIds::only({7})) << "the first edit of a kind brings its ids";
    EXPECT_EQ(delta.materials, TouchedIds::only({1, 2, 3})) << "an edit of another kind leaves them";
    delta |= SceneChanges::Materials;  // an edit that did not say which material
    EXPECT_TRUE(delta.materials.every);
    delta |= materialsEdited({0});
    EXPECT_TRUE(delta.materials.every) << "every stays every";
    EXPECT_EQ(delta.meshes, TouchedIds::only({7}));
}

TEST(SceneDelta, TheIdsBelowACount) {
    EXPECT_EQ(TouchedIds::only({5, 1, 9}).below(6), (std::vector<uint32_t>{1, 5}));
    EXPECT_EQ(TouchedIds{}.below(3), (std::vector<uint32_t>{0, 1, 2}));
}

TEST(SceneDelta, WithoutDropsTheBitsAndTheirIds) {
    SceneDelta delta = instancesMoved({4});
    delta |= SceneChanges::Display;
    const SceneDelta kept = delta.without(SceneChanges::Display);
    EXPECT_EQ(kept, instancesMoved({4}));
    const SceneDelta none = delta.without(SceneChanges::Transforms | SceneChanges::Display);
    EXPECT_EQ(none.mask, SceneChanges::None);
    EXPECT_TRUE(none.instances.every) << "ids without their bit are forgotten";
}

TEST(SceneDelta, EqualityComparesTheIdsTheBitsName) {
    EXPECT_NE(materialsEdited({1}), SceneDelta(SceneChanges::Materials));
    EXPECT_NE(materialsEdited({1}), materialsEdited({2}));
    SceneDelta a = SceneChanges::Camera, b = SceneChanges::Camera;
    b.materials = TouchedIds::only({9});  // no Materials bit: not part of the delta
    EXPECT_EQ(a, b);
}

}  // namespace
}  // namespace pt
