// EditorSession on the CPU backend: opening files (errors keep the document), edits turned
// into the SceneChanges the backend syncs, display-only edits that keep the accumulation, the
// target spp, edit latency, undo, export and save.
//
// The tests wrap the CPU backend in one that records what the session asked of it and reports
// the action the CUDA backend takes for those changes ("materials", "TLAS", ...): what the tests
// check is that the session passes each edit's changes and reports the backend's answer.
#include "editor/editor_session.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <future>
#include <memory>
#include <string>
#include <thread>

#include "assets/image/exr_layers.h"
#include "assets/image/image_metadata.h"
#include "assets/image/image_read.h"
#include "assets/image/image_write.h"
#include "assets/input_error.h"
#include "assets/scene_json/scene_json.h"
#include "assets/scene_test_helpers.h"
#include "editor/color_view.h"
#include "editor/scene_edits.h"
#include "editor/scene_equality.h"
#include "support/load_scene.h"
#include "support/scene_builder.h"
#include "support/test_paths.h"

namespace pt::editor {
namespace {

using test::addMaterial;
using test::addShape;
using test::diffuse;
using test::trs;

// The CPU backend, recording every sync's changes.
class RecordingBackend final : public Backend {
public:
    std::vector<SceneDelta> syncs;

    std::string name() const override { return "recording " + cpu_->name(); }
    SyncReport sync(const Scene& scene, const SceneDelta& changes, const ProgressFn& progress) override {
        syncs.push_back(changes);
        SyncReport report = cpu_->sync(scene, changes, progress);
        report.action = actionFor(changes.mask);
        return report;
    }
    void setToggles(const IntegratorToggles& toggles) override { cpu_->setToggles(toggles); }
    void render(uint32_t passes) override { cpu_->render(passes); }
    void setInterruptFlag(const std::atomic<bool>* flag) override { cpu_->setInterruptFlag(flag); }
    void resetAccumulation() override { cpu_->resetAccumulation(); }
    uint32_t width() const override { return cpu_->width(); }
    uint32_t height() const override { return cpu_->height(); }
    void readBeauty(std::vector<float>& rgba) const override { cpu_->readBeauty(rgba); }
    BackendStats stats() const override { return cpu_->stats(); }
    std::vector<ToggleState> toggleStates() const override { return cpu_->toggleStates(); }
    std::vector<double> traceRays(const std::vector<Ray>& rays, bool anyHit, uint32_t runs,
                                  std::vector<Hit>* hits) override {
        return cpu_->traceRays(rays, anyHit, runs, hits);
    }
    int32_t sceneInstance(uint32_t hitInstance) const override { return cpu_->sceneInstance(hitInstance); }
    uint64_t deviceMemoryBytes() const override { return cpu_->deviceMemoryBytes(); }
    void setAovs(AovMask aovs) override { cpu_->setAovs(aovs); }
    void changeAovs(AovMask aovs) override { cpu_->changeAovs(aovs); }
    AovMask aovs() const override { return cpu_->aovs(); }
    uint32_t aovSamples(Aov aov) const override { return cpu_->aovSamples(aov); }
    void setAovSampleCap(const AovSampleCap& cap) override { cpu_->setAovSampleCap(cap); }
    AovSampleCap aovSampleCap() const override { return cpu_->aovSampleCap(); }
    void readAov(Aov aov, std::vector<float>& rgba) const override { cpu_->readAov(aov, rgba); }
    uint64_t aovBytes() const override { return cpu_->aovBytes(); }

private:
    // The CUDA backend's names for the least work each change needs (render/backend/backend.h).
    static std::string actionFor(SceneChangeMask changes) {
        if (changes & (SceneChanges::Topology | SceneChanges::Textures)) return "full build";
        if (changes & SceneChanges::Geometry) return "refit";
        if (changes & SceneChanges::Transforms) return "TLAS";
        if (changes & SceneChanges::Materials) return "materials";
        if (changes & (SceneChanges::Lights | SceneChanges::Environment)) return "lights";
        return changes == SceneChanges::None ? "nothing" : "reset";
    }

    std::unique_ptr<Backend> cpu_ = createBackend("cpu");
};

// A 16x16 scene: a sphere and a box under an emitting quad.
Scene tinyScene() {
    Scene scene;
    scene.render = {16, 16, 2, 4, 0};
    scene.camera.position = {0, 0, 5};
    scene.camera.lookAt = {0, 0, 0};
    const uint32_t red = addMaterial(scene, "red", diffuse({0.8f, 0.1f, 0.1f}));
    const uint32_t blue = addMaterial(scene, "blue", diffuse({0.1f, 0.1f, 0.8f}));
    const uint32_t lamp = addMaterial(scene, "lamp", test::emitter({4, 4, 4}));
    addShape(scene, ObjectKind::Sphere, trs({-1, 0, 0}, {0, 0, 0}, {0.7f, 0.7f, 0.7f}), red, "ball");
    addShape(scene, ObjectKind::Box, trs({1, 0, 0}, {0, 30, 0}, {0.5f, 0.5f, 0.5f}), blue, "crate");
    addShape(scene, ObjectKind::Quad, trs({0, 2, 0}, {180, 0, 0}, {2, 1, 2}), lamp, "lamp");
    scene.environment.color = {0.1f, 0.1f, 0.1f};
    return scene;
}

struct Fixture {
    RecordingBackend* backend;
    std::unique_ptr<EditorSession> session;
};

// A session on the tiny scene, synced, with `spp` samples rendered.
Fixture startSession(uint32_t spp = 1) {
    auto backend = std::make_unique<RecordingBackend>();
    Fixture f{backend.get(), std::make_unique<EditorSession>(std::move(backend))};
    f.session->adopt(tinyScene());
    EXPECT_EQ(f.session->pendingChanges().mask, SceneChanges::All);
    f.session->sync();
    EXPECT_EQ(f.session->pendingChanges().mask, SceneChanges::None);
    f.session->render(spp);
    return f;
}

Material edited(const EditorSession& session, uint32_t material) {
    Material m = session.document().scene.materials[material].params;
    m.baseColor = {0.2f, 0.9f, 0.2f};
    return m;
}

TEST(EditorSession, OpenFailuresNameTheFileAndKeepTheDocument) {
    Fixture f = startSession();
    EditorSession& session = *f.session;
    session.execute(setMaterial(session.document(), 0, edited(session, 0)));
    const Scene before = session.document().scene;

    const std::string folder = test::testFolder();
    const std::string missing = folder + "/missing scene.json";
    const std::string error = session.open(missing);
    EXPECT_NE(error.find("missing scene.json"), std::string::npos) << error;

    const std::string malformed =
        test::writeFile(folder, "malformed.json", "{\"version\": 1, \"objects\": [");
    const std::string error2 = session.open(malformed);
    EXPECT_NE(error2.find("malformed.json"), std::string::npos) << error2;

    test::expectScenesEqual(before, session.document().scene);
    EXPECT_TRUE(session.history().canUndo()) << "the history of the kept document stays";
    EXPECT_TRUE(session.modified());
}

// A new document's exposure starts at 0 stops: the previous file's does not carry over.
TEST(EditorSession, ExposureDoesNotLeakIntoTheNextFile) {
    Fixture f = startSession();
    EditorSession& session = *f.session;
    ViewerSettings viewer = session.document().viewer;
    viewer.display.exposureStops = -9.0f;
    viewer.aov = int32_t(Aov::Albedo);
    session.execute(setViewer(session.document(), viewer));
    session.adopt(tinyScene());
    EXPECT_EQ(session.document().viewer.display.exposureStops, 0.0f);
    EXPECT_EQ(session.document().viewer.aov, int32_t(Aov::Albedo)) << "the other view choices stay";
}

TEST(EditorSession, OpenReplacesTheDocument) {
    Fixture f = startSession();
    EditorSession& session = *f.session;
    session.execute(setMaterial(session.document(), 0, edited(session, 0)));
    session.sync();
    EXPECT_EQ(session.open(test::projectPath("scenes/cornell.json")), "");
    EXPECT_EQ(session.document().scene.objects.size(), 8u);
    EXPECT_EQ(session.pendingChanges().mask, SceneChanges::All);
    EXPECT_FALSE(session.history().canUndo());
    EXPECT_FALSE(session.modified());
}

TEST(EditorSession, AMaterialEditSyncsMaterials) {
    Fixture f = startSession();
    EditorSession& session = *f.session;
    const size_t syncs = f.backend->syncs.size();
    EXPECT_EQ(session.execute(setMaterial(session.document(), 1, edited(session, 1))).mask,
              SceneChanges::Materials);
    EXPECT_EQ(session.pendingChanges().mask, SceneChanges::Materials);
    EXPECT_FALSE(session.lastEdit().complete);
    const SyncReport report = session.sync();
    ASSERT_EQ(f.backend->syncs.size(), syncs + 1);
    EXPECT_EQ(f.backend->syncs.back().mask, SceneChanges::Materials);
    EXPECT_EQ(f.backend->syncs.back().materials.ids, std::vector<uint32_t>{1})
        << "the edit names its material";
    EXPECT_FALSE(f.backend->syncs.back().materials.every);
    EXPECT_EQ(report.action, "materials");
    EXPECT_EQ(session.lastEdit().action, "materials");
    EXPECT_EQ(session.backend().stats().samplesPerPixel, 0u) << "the edit restarts accumulation";
    EXPECT_FALSE(session.lastEdit().complete) << "no frame yet";
    EXPECT_EQ(session.render(1), 1u);
    const EditLatency& latency = session.lastEdit();
    EXPECT_TRUE(latency.complete);
    EXPECT_GT(latency.toFrameSeconds, 0.0);
    EXPECT_GE(latency.toFrameSeconds, latency.syncSeconds);
    // It counts from the command handed over: its apply, then the sync, then the pass.
    EXPECT_GE(latency.toFrameSeconds, latency.applySeconds + latency.syncSeconds);
    EXPECT_EQ(latency.label, "Edit material blue");
    // Later frames do not move the measurement.
    const double measured = latency.toFrameSeconds;
    session.render(1);
    EXPECT_EQ(session.lastEdit().toFrameSeconds, measured);
}

TEST(EditorSession, AnObjectMoveSyncsTheTlas) {
    Fixture f = startSession();
    EditorSession& session = *f.session;
    EXPECT_EQ(session.execute(setObjectTransform(session.document(), 0, trs({-1, 0.5f, 0}))).mask,
              SceneChanges::Transforms);
    EXPECT_EQ(session.sync().action, "TLAS");
    EXPECT_EQ(f.backend->syncs.back().mask, SceneChanges::Transforms);
    std::vector<uint32_t> objectInstances;  // the instances object 0 places
    for (uint32_t i = 0; i < session.document().scene.instances.size(); ++i) {
        if (session.document().scene.instances[i].object == 0) objectInstances.push_back(i);
    }
    ASSERT_FALSE(objectInstances.empty());
    EXPECT_EQ(f.backend->syncs.back().instances.ids, objectInstances);
    EXPECT_FALSE(f.backend->syncs.back().instances.every);
    EXPECT_EQ(session.lastEdit().action, "TLAS");
}

TEST(EditorSession, ADisplayEditKeepsTheAccumulation) {
    Fixture f = startSession(2);
    EditorSession& session = *f.session;
    session.execute(setMaterial(session.document(), 0, edited(session, 0)));
    session.sync();
    session.render(2);
    const EditLatency latency = session.lastEdit();
    ASSERT_TRUE(latency.complete);
    const size_t syncs = f.backend->syncs.size();

    ViewerSettings viewer = session.document().viewer;
    viewer.display.exposureStops = 2.0f;
    EXPECT_EQ(session.execute(setViewer(session.document(), viewer)).mask, SceneChanges::Display);
    EXPECT_EQ(session.pendingChanges().mask, SceneChanges::Display);
    EXPECT_EQ(session.sync().action, "nothing");
    EXPECT_EQ(f.backend->syncs.size(), syncs) << "the backend is not asked to sync";
    EXPECT_EQ(session.pendingChanges().mask, SceneChanges::None);
    EXPECT_EQ(session.backend().stats().samplesPerPixel, 2u);
    EXPECT_EQ(session.document().viewer.display.exposureStops, 2.0f);
    EXPECT_EQ(session.lastEdit().label, latency.label) << "a display edit is not an edit to render";
    EXPECT_TRUE(session.lastEdit().complete);
}

// Showing an AOV is a display change: the beauty keeps its samples and the AOV accumulates from
// there (it restarted the accumulation: issue 20, defect 8); back on the beauty, it is freed.
TEST(EditorSession, SwitchingTheAovKeepsTheAccumulation) {
    Fixture f = startSession(4);
    EditorSession& session = *f.session;
    const size_t syncs = f.backend->syncs.size();
    ViewerSettings viewer = session.document().viewer;
    viewer.aov = int32_t(Aov::ShadingNormal);
    session.execute(setViewer(session.document(), viewer));
    EXPECT_EQ(session.sync().action, "nothing");
    EXPECT_EQ(f.backend->syncs.size(), syncs);
    EXPECT_EQ(session.render(2), 2u);
    EXPECT_EQ(session.backend().stats().samplesPerPixel, 6u);
    EXPECT_EQ(session.backend().aovSamples(Aov::ShadingNormal), 2u);
    std::vector<float> shown, normal;
    session.readDisplayed(viewer.aov, false, shown);
    session.backend().readAov(Aov::ShadingNormal, normal);
    EXPECT_EQ(shown, normal);

    viewer.aov = -1;
    session.execute(setViewer(session.document(), viewer));
    EXPECT_EQ(session.sync().action, "nothing");
    EXPECT_EQ(session.backend().aovs(), 0u);
    EXPECT_EQ(session.backend().stats().samplesPerPixel, 6u);
}

// Turns the viewer's Denoise switch on or off and syncs.
SyncReport setDenoise(EditorSession& session, bool on) {
    ViewerSettings viewer = session.document().viewer;
    viewer.denoise = on;
    session.execute(setViewer(session.document(), viewer));
    return session.sync();
}

// Denoise: turning it on restarts the accumulation once (its guides accumulate from there);
// the viewport and the export's display image show the denoised beauty, the EXR keeps the raw
// one with the denoised beside it; turning it off is a display change that keeps the samples.
TEST(EditorSession, DenoiseShowsTheFilteredBeautyAndTurnsOffWithoutARestart) {
    Fixture f = startSession(2);
    EditorSession& session = *f.session;
    EXPECT_NE(setDenoise(session, true).action, "nothing") << "the guides need a fresh accumulation";
    const ViewerSettings viewer = session.document().viewer;
    EXPECT_EQ(session.backend().aovs() & kDenoiseGuideAovs, kDenoiseGuideAovs);
    session.render(4);
    std::vector<float> shown, denoised, raw;
    session.readDisplayed(-1, true, shown);
    session.backend().readDenoised(denoised);
    session.backend().readBeauty(raw);
    EXPECT_EQ(shown, denoised);
    EXPECT_NE(shown, raw) << "4 noisy samples pass the denoiser unchanged";
    EXPECT_GT(session.lastDenoiseSeconds(), 0.0);

    if (PT_TEST_HAVE_OIIO) {
        const std::string exr = test::testFolder() + "/denoised.exr";
        session.exportRender(exr, "", DisplayProcessor(viewer.display));
        const ExrImage image = readExrChannels(exr);
        const ExrChannelData *r = image.channel("R"), *denoisedR = image.channel("denoised.R");
        ASSERT_TRUE(r && denoisedR);
        for (size_t i = 0; i < raw.size() / 4; ++i) {
            ASSERT_EQ(r->values[i], raw[4 * i]) << i;
            ASSERT_EQ(denoisedR->values[i], denoised[4 * i]) << i;
        }
    }

    EXPECT_EQ(setDenoise(session, false).action, "nothing");
    EXPECT_EQ(session.backend().stats().samplesPerPixel, 4u);
    session.readDisplayed(-1, false, shown);
    EXPECT_EQ(shown, raw);
}

// The guides stop at kSettledGuideSamples while the denoiser goes on using them, the variance
// follows the beauty, and an AOV the user looks at goes on in full: viewing the albedo lifts its
// cap (a display change, no restart).
TEST(EditorSession, DenoiseGuidesSettleButAViewedAovGoesOn) {
    Fixture f = startSession(1);
    EditorSession& session = *f.session;
    setDenoise(session, true);
    const uint32_t settled = kSettledGuideSamples;
    session.render(settled);
    session.render(20);  // the guides are full from the start of this call
    const Backend& backend = session.backend();
    EXPECT_EQ(backend.stats().samplesPerPixel, settled + 20);
    EXPECT_EQ(backend.aovSamples(Aov::Albedo), settled);
    EXPECT_EQ(backend.aovSamples(Aov::Depth), settled);
    EXPECT_EQ(backend.aovSamples(Aov::Variance), settled + 20);
    std::vector<float> shown, denoised;
    session.readDisplayed(-1, true, shown);
    backend.readDenoised(denoised);
    EXPECT_EQ(shown, denoised) << "settled guides still guide";

    ViewerSettings viewer = session.document().viewer;
    viewer.aov = int32_t(Aov::Albedo);
    session.execute(setViewer(session.document(), viewer));
    EXPECT_EQ(session.sync().action, "nothing");
    session.render(5);
    EXPECT_EQ(backend.aovSamples(Aov::Albedo), settled + 5) << "the viewed AOV goes on";
    EXPECT_EQ(backend.aovSamples(Aov::Depth), settled);
    EXPECT_EQ(backend.stats().samplesPerPixel, settled + 25);
    session.readDisplayed(-1, true, shown);
    backend.readDenoised(denoised);
    EXPECT_EQ(shown, denoised) << "a settled guide the user views still guides";

    // An export layer that is a guide goes on in full too, and the denoiser keeps going.
    viewer.aov = -1;
    viewer.exportAovs = aovBit(Aov::Depth);
    session.execute(setViewer(session.document(), viewer));
    EXPECT_EQ(session.sync().action, "nothing");
    session.render(5);
    EXPECT_EQ(backend.aovSamples(Aov::Depth), settled + 5);
    EXPECT_EQ(backend.aovSamples(Aov::Albedo), settled + 5) << "stopped again only by a full cap";
    EXPECT_TRUE(denoiseGuidesComplete(backend));
    session.readDisplayed(-1, true, shown);
    backend.readDenoised(denoised);
    EXPECT_EQ(shown, denoised);
}

// An edit that restarts the accumulation stops the pass in flight on the render thread (its
// samples are of the old scene) instead of waiting for it: here a pass of hours.
TEST(EditorSession, AnEditStopsThePassInFlight) {
    Fixture f = startSession(1);
    EditorSession& session = *f.session;
    auto pass = std::async(std::launch::async, [&] { return session.render(100'000'000, 0); });
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
    Camera camera = session.document().scene.camera;
    camera.position.x += 0.1f;
    session.execute(setCamera(session.document(), camera));
    if (pass.wait_for(std::chrono::seconds(120)) != std::future_status::ready) {
        std::fprintf(stderr, "the camera edit did not stop the pass in flight\n");
        std::abort();  // the pass would hold the test process for hours
    }
    EXPECT_EQ(pass.get(), 0u) << "an interrupted pass is no sample";
    EXPECT_FALSE(session.lastEdit().complete) << "the edit's frame is still to come";
    EXPECT_EQ(session.render(1, 0), 0u) << "nothing renders before the edit is synced";
    EXPECT_EQ(session.sync().action, "reset");
    EXPECT_EQ(session.render(2, 0), 2u);
    EXPECT_EQ(session.backend().stats().samplesPerPixel, 2u);
    EXPECT_TRUE(session.lastEdit().complete);
}

// A display edit keeps the accumulation, so it lets the pass in flight finish; so does a new
// backend's first sync (the flag is the session's, handed to every backend it holds).
TEST(EditorSession, ADisplayEditLetsThePassFinish) {
    Fixture f = startSession(1);
    EditorSession& session = *f.session;
    ViewerSettings viewer = session.document().viewer;
    viewer.display.exposureStops = 1.0f;
    session.execute(setViewer(session.document(), viewer));
    EXPECT_EQ(session.render(3, 0), 3u);
    EXPECT_EQ(session.sync().action, "nothing");
    EXPECT_EQ(session.backend().stats().samplesPerPixel, 4u);

    session.setBackend(createBackend("cpu"));
    session.sync();
    EXPECT_EQ(session.render(2, 0), 2u);
    session.interruptRender();
    EXPECT_EQ(session.render(2, 0), 0u) << "the new backend watches the session's flag";
    EXPECT_EQ(session.backend().stats().samplesPerPixel, 0u);
}

// With interrupts off (the edit bench's baseline), the pass in flight when an edit comes ends
// normally; it shows the scene before the edit, so it is not the edit's first frame.
TEST(EditorSession, APassBeforeTheEditsSyncIsNotItsFirstFrame) {
    Fixture f = startSession(1);
    EditorSession& session = *f.session;
    session.setPassInterrupts(false);
    Camera camera = session.document().scene.camera;
    camera.position.x += 0.1f;
    session.execute(setCamera(session.document(), camera));
    EXPECT_EQ(session.render(1, 0), 1u);
    EXPECT_FALSE(session.lastEdit().complete);
    session.sync();
    EXPECT_EQ(session.render(1, 0), 1u);
    EXPECT_TRUE(session.lastEdit().complete);
}

TEST(EditorSession, RenderStopsAtTheTargetSpp) {
    Fixture f = startSession(0);
    EditorSession& session = *f.session;
    ViewerSettings viewer = session.document().viewer;
    viewer.targetSpp = 3;
    session.execute(setViewer(session.document(), viewer));
    session.sync();
    EXPECT_FALSE(session.converged());
    EXPECT_EQ(session.render(2), 2u);
    EXPECT_EQ(session.render(2), 1u);
    EXPECT_EQ(session.render(2), 0u);
    EXPECT_EQ(session.backend().stats().samplesPerPixel, 3u);
    EXPECT_TRUE(session.converged());
    // No target: renders what it is asked.
    viewer.targetSpp = 0;
    session.execute(setViewer(session.document(), viewer));
    EXPECT_EQ(session.render(2), 2u);
    EXPECT_FALSE(session.converged());
}

TEST(EditorSession, UndoAndRedoSyncLikeTheEdit) {
    Fixture f = startSession();
    EditorSession& session = *f.session;
    const Scene before = session.document().scene;
    session.execute(setMaterial(session.document(), 1, edited(session, 1)));
    const std::string action = session.sync().action;
    session.render(1);
    const Scene after = session.document().scene;

    ASSERT_TRUE(session.undo());
    EXPECT_EQ(session.pendingChanges().mask, SceneChanges::Materials);
    EXPECT_EQ(session.sync().action, action);
    EXPECT_EQ(f.backend->syncs.back().mask, SceneChanges::Materials);
    test::expectScenesEqual(before, session.document().scene);
    EXPECT_EQ(session.lastEdit().label, "Undo Edit material blue");
    EXPECT_FALSE(session.lastEdit().complete);
    session.render(1);
    EXPECT_TRUE(session.lastEdit().complete);
    EXPECT_FALSE(session.undo()) << "nothing more to undo";

    ASSERT_TRUE(session.redo());
    EXPECT_EQ(session.sync().action, action);
    EXPECT_EQ(session.lastEdit().label, "Redo Edit material blue");
    test::expectScenesEqual(after, session.document().scene);
    EXPECT_FALSE(session.redo());
}

TEST(EditorSession, ExportWritesTheBeautyAndItsDisplayImage) {
    Fixture f = startSession(2);
    EditorSession& session = *f.session;
    ViewerSettings viewer = session.document().viewer;
    viewer.display.exposureStops = 1.0f;
    viewer.display.toneMapper = ToneMapper::Reinhard;
    session.execute(setViewer(session.document(), viewer));
    std::vector<float> beauty;
    session.backend().readBeauty(beauty);
    ASSERT_EQ(beauty.size(), 16u * 16u * 4u);

    const std::string folder = test::testFolder();
    const std::string png = folder + "/render.png";
    const std::string exr = PT_TEST_HAVE_OIIO ? folder + "/render.exr" : std::string();
    session.exportRender(exr, png, DisplayProcessor(viewer.display));

    const Texture image = readTextureFile(png);
    ASSERT_EQ(image.width, 16u);
    ASSERT_EQ(image.height, 16u);
    ASSERT_EQ(image.format, TexelFormat::RGBA8);
    const std::vector<uint8_t> expected = encodeDisplay8(beauty, 16u, viewer.display);
    size_t differing = 0;
    for (size_t i = 0; i < 16u * 16u; ++i) {
        for (size_t c = 0; c < 3; ++c) differing += image.texels8[i * 4 + c] != expected[i * 3 + c] ? 1 : 0;
    }
    EXPECT_EQ(differing, 0u) << "PNG pixels differ from encodeDisplay8 of the beauty";
    // Exposure + Reinhard must show: the plain sRGB encoding gives other pixels.
    EXPECT_NE(encodeDisplay8(beauty, 16u, DisplaySettings{}), expected);

    if (!PT_TEST_HAVE_OIIO) GTEST_SKIP() << "this build has no OpenImageIO (PT_OIIO=OFF): no EXR";
    uint32_t w = 0, h = 0;
    const std::vector<float> read = readImageRgba(exr, w, h);
    ASSERT_EQ(w, 16u);
    ASSERT_EQ(h, 16u);
    ASSERT_EQ(read.size(), beauty.size());
    for (size_t i = 0; i < beauty.size(); ++i) {
        if (i % 4 == 3) continue;  // alpha
        ASSERT_EQ(read[i], beauty[i]) << "EXR value " << i;
    }
}

// Export layers accumulate beside the displayed AOV from the next sync, which keeps the beauty's
// samples (a display change); an export writes those accumulated, at the viewer's precision.
TEST(EditorSession, ExportLayersAccumulateAfterTheirEditAndGoIntoTheExr) {
    auto recording = std::make_unique<RecordingBackend>();
    Fixture f{recording.get(), std::make_unique<EditorSession>(std::move(recording))};
    EditorSession& session = *f.session;
    Scene scene = tinyScene();
    scene.color.display = "sRGB";
    scene.color.view = "AgX";
    session.adopt(scene);
    session.sync();
    session.render(2);
    EXPECT_EQ(session.backend().aovs(), 0u);
    EXPECT_EQ(session.backend().aovBytes(), 0u) << "nothing displayed or exported: no AOV memory";
    const AovMask exported = aovBit(Aov::Albedo) | aovBit(Aov::InstanceId);
    ViewerSettings viewer = session.document().viewer;
    viewer.exportAovs = exported;
    viewer.exportHalf = true;
    viewer.aov = int32_t(Aov::Depth);  // shown, so accumulated too, but not chosen for export
    session.execute(setViewer(session.document(), viewer));
    const std::string folder = test::testFolder();
    if (PT_TEST_HAVE_OIIO) {
        EXPECT_EQ(session.exportRender(folder + "/early.exr", "", DisplayProcessor(viewer.display)), 0u)
            << "not accumulated before the sync";
        EXPECT_EQ(readExrChannels(folder + "/early.exr").channels.size(), 4u);
    }
    const size_t syncs = f.backend->syncs.size();
    EXPECT_EQ(session.sync().action, "nothing");
    EXPECT_EQ(f.backend->syncs.size(), syncs) << "new AOVs need no sync (issue 20, defect 8)";
    EXPECT_EQ(session.backend().aovs(), exported | aovBit(Aov::Depth));
    EXPECT_EQ(session.backend().stats().samplesPerPixel, 2u) << "the beauty keeps its samples";
    EXPECT_EQ(session.backend().aovSamples(Aov::Albedo), 0u);
    session.render(2);
    EXPECT_EQ(session.backend().aovSamples(Aov::Albedo), 2u);
    EXPECT_EQ(session.backend().stats().samplesPerPixel, 4u);

    if (!PT_TEST_HAVE_OIIO) GTEST_SKIP() << "this build has no OpenImageIO (PT_OIIO=OFF): no EXR";
    const std::string exr = folder + "/layers.exr";
    // Through the scene's OpenColorIO view, as the editor's viewport shows it.
    const ColorView color = resolveColorView("", session.document().scene.color, {});
    const DisplayProcessor display = displayProcessorFor(color, session.document().viewer);
    EXPECT_EQ(session.exportRender(exr, folder + "/layers.png", display), exported);
    const ExrImage image = readExrChannels(exr);
    std::vector<std::string> names;
    for (const ExrChannelData& c : image.channels) names.push_back(c.name);
    std::sort(names.begin(), names.end());
    EXPECT_EQ(names, (std::vector<std::string>{"A", "B", "G", "R", "albedo.B", "albedo.G", "albedo.R",
                                               "instance_id.Y"}));
    EXPECT_EQ(image.channel("R")->type, ExrPixelType::Half);
    EXPECT_EQ(image.channel("albedo.R")->type, ExrPixelType::Half);
    EXPECT_EQ(image.channel("instance_id.Y")->type, ExrPixelType::Float);
    std::vector<float> albedo, ids;
    session.backend().readAov(Aov::Albedo, albedo);
    session.backend().readAov(Aov::InstanceId, ids);
    for (size_t i = 0; i < 16u * 16u; ++i) {
        ASSERT_NEAR(image.channel("albedo.G")->values[i], albedo[i * 4 + 1], albedo[i * 4 + 1] * 0x1p-11f)
            << i;
        ASSERT_EQ(image.channel("instance_id.Y")->values[i], ids[i * 4]) << i;
    }
    EXPECT_EQ(image.attribute("pt:aovs"), "albedo,instance_id");
    EXPECT_EQ(image.attribute("pt:spp"), "4");
    EXPECT_EQ(image.attribute("pt:camera_position"), "0 0 5");
    EXPECT_EQ(image.attribute("pt:view"), display.describe());
#ifdef PT_HAVE_OCIO
    EXPECT_NE(image.attribute("pt:view").find("sRGB / AgX"), std::string::npos) << image.attribute("pt:view");
    EXPECT_EQ(image.attribute("pt:ocio_config"), color.config->path());
    // The PNG holds the view's bytes: those of the CPU display path for the same beauty.
    std::vector<float> beauty;
    session.backend().readBeauty(beauty);
    const Texture png = readTextureFile(folder + "/layers.png");
    const std::vector<uint8_t> expected = display.encode8(beauty, 16u, viewer.display.dither);
    for (size_t i = 0; i < 16u * 16u; ++i) {
        for (size_t c = 0; c < 3; ++c) ASSERT_EQ(png.texels8[i * 4 + c], expected[i * 3 + c]) << i;
    }
    EXPECT_NE(expected, DisplayProcessor(viewer.display).encode8(beauty, 16u, viewer.display.dither))
        << "AgX and the plain sRGB encoding differ on this scene";
#endif

    // Choosing none (and showing the beauty) frees the AOV memory at the next sync.
    viewer.exportAovs = 0;
    viewer.aov = -1;
    session.execute(setViewer(session.document(), viewer));
    session.sync();
    EXPECT_EQ(session.backend().aovs(), 0u);
    EXPECT_EQ(session.backend().aovBytes(), 0u);
}

// A render that follows the viewport overrides the resolution at every resize: saving still
// writes the file's own, and turning the following off goes back to it. A resolution the user
// sets is theirs: saved, and not taken back.
TEST(EditorSession, ResolutionOverridesKeepTheFilesResolution) {
    Fixture f = startSession();
    EditorSession& session = *f.session;
    const std::string path = test::testFolder() + "/overridden.json";
    session.overrideResolution(40, 30);
    session.overrideResolution(64, 48);
    session.sync();
    EXPECT_EQ(session.backend().width(), 64u);
    EXPECT_FALSE(session.modified()) << "an override is not an edit";
    session.save(path);
    EXPECT_EQ(test::loadSceneOrFail(path).render.width, 16u);
    EXPECT_EQ(session.document().scene.render.width, 64u) << "the render keeps its size after saving";

    session.restoreResolution();
    EXPECT_EQ(session.pendingChanges().mask & SceneChanges::Settings, SceneChanges::Settings);
    session.sync();
    EXPECT_EQ(session.backend().width(), 16u);
    EXPECT_EQ(session.backend().height(), 16u);

    session.overrideResolution(64, 48);
    RenderSettings typed = session.document().scene.render;
    typed.width = 100;
    typed.height = 50;
    session.execute(setRenderSettings(session.document(), typed));
    session.restoreResolution();
    EXPECT_EQ(session.document().scene.render.width, 100u) << "the user's resolution stays";
    session.save(path);
    EXPECT_EQ(test::loadSceneOrFail(path).render.width, 100u);
}

TEST(EditorSession, SaveWritesTheSceneAndClearsModified) {
    Fixture f = startSession();
    EditorSession& session = *f.session;
    EXPECT_FALSE(session.modified());
    const Material m = edited(session, 0);
    session.execute(setMaterial(session.document(), 0, m));
    EXPECT_TRUE(session.modified());
    const std::string folder = test::testFolder();
    const std::string path = folder + "/saved.json";
    session.save(path);
    EXPECT_FALSE(session.modified());
    const Scene loaded = test::loadSceneOrFail(path);
    const int32_t red = loaded.findMaterial("red");
    ASSERT_GE(red, 0);
    EXPECT_EQ(std::memcmp(&loaded.materials[size_t(red)].params, &m, sizeof(Material)), 0);
    EXPECT_EQ(loaded.objects.size(), session.document().scene.objects.size());
    // Undoing past the save modifies the document again.
    session.undo();
    EXPECT_TRUE(session.modified());
    // A failing save throws and keeps the modified flag.
    EXPECT_THROW(session.save(folder + "/missing folder/x.json"), InputError);
    EXPECT_TRUE(session.modified());
}

// Values typed past what the scene reader accepts (a field of view of 0, roughness -1, an IOR
// of 0, a negative colour, an infinite angle) are held in range by the edit, so the saved scene
// reopens with them.
TEST(EditorSession, TypedValuesOutOfRangeAreHeldSoTheSavedSceneReopens) {
    Fixture f = startSession();
    EditorSession& session = *f.session;
    Camera camera = session.document().scene.camera;
    camera.verticalFovDegrees = 0.0f;
    camera.apertureRadius = -2.0f;
    session.execute(setCamera(session.document(), camera));
    EXPECT_EQ(session.document().scene.camera.verticalFovDegrees, kMinEditedFov);
    EXPECT_EQ(session.document().scene.camera.apertureRadius, 0.0f);
    camera.verticalFovDegrees = 1e9f;
    camera.apertureRadius = 1e9f;  // absurd, but a scene may hold it
    session.execute(setCamera(session.document(), camera));
    EXPECT_EQ(session.document().scene.camera.verticalFovDegrees, kMaxEditedFov);
    EXPECT_EQ(session.document().scene.camera.apertureRadius, 1e9f);

    Material m = session.document().scene.materials[0].params;
    m.roughness = -1.0f;
    m.ior = 0.0f;
    m.baseColor = {2.0f, -1.0f, 0.5f};
    m.emissionStrength = std::nanf("");
    m.dispersion = -1.0f;
    m.iridescenceIor = 0.5f;
    m.anisotropyStrength = 3.0f;
    m.anisotropyRotation = kInf;  // degrees in the file: no finite number
    session.execute(setMaterial(session.document(), 0, m));
    const Material& held = session.document().scene.materials[0].params;
    EXPECT_EQ(held.roughness, 0.0f);
    EXPECT_EQ(held.ior, 1.0f);
    EXPECT_EQ(held.baseColor.x, 1.0f);
    EXPECT_EQ(held.baseColor.y, 0.0f);
    EXPECT_EQ(held.baseColor.z, 0.5f);
    EXPECT_EQ(held.emissionStrength, 0.0f);
    EXPECT_EQ(held.dispersion, 0.0f);
    EXPECT_EQ(held.iridescenceIor, 1.0f);
    EXPECT_EQ(held.anisotropyStrength, 1.0f);
    EXPECT_EQ(held.anisotropyRotation, 0.0f);
    EXPECT_EQ(held.attenuationDistance, Material{}.attenuationDistance) << "a default stays (infinity)";

    const std::string path = test::testFolder() + "/typed.json";
    session.save(path);
    const LoadResult reopened = loadScene(path);
    ASSERT_TRUE(reopened.ok()) << reopened.error;
    EXPECT_EQ(reopened.scene->camera.verticalFovDegrees, kMaxEditedFov);
    EXPECT_EQ(reopened.scene->materials[0].params.ior, 1.0f);
    EXPECT_EQ(reopened.scene->materials[0].params.roughness, 0.0f);
    EXPECT_EQ(reopened.scene->materials[0].params.anisotropyStrength, 1.0f);
}

// After Save As the document is the new file: an export names it (not the file it was opened
// from, which lacks the edits), and a failed save leaves the name alone.
TEST(EditorSession, SaveAsMakesTheDocumentTheNewFile) {
    Fixture f = startSession(1);
    EditorSession& session = *f.session;
    const std::string opened = session.document().scene.sourcePath;
    const std::string folder = test::testFolder();
    const std::string path = folder + "/saved as.json";
    session.save(path);
    const std::string expected = std::filesystem::absolute(path).lexically_normal().string();
    EXPECT_NE(opened, expected);
    EXPECT_EQ(session.document().scene.sourcePath, expected);
    EXPECT_THROW(session.save(folder + "/missing folder/x.json"), InputError);
    EXPECT_EQ(session.document().scene.sourcePath, expected);
    if (!PT_TEST_HAVE_OIIO) GTEST_SKIP() << "this build has no OpenImageIO (PT_OIIO=OFF): no EXR metadata";
    const std::string exr = folder + "/after save as.exr";
    session.exportRender(exr, "", DisplayProcessor(session.document().viewer.display));
    std::string named;
    for (const auto& [key, value] : readImageMetadata(exr)) {
        if (key == "pt:scene") named = value;
    }
    EXPECT_EQ(named, expected);
}

// The window's title names the document's file and marks unsaved edits with "*".
TEST(EditorSession, TheWindowTitleNamesTheFileAndMarksUnsavedEdits) {
    Fixture f = startSession();
    EditorSession& session = *f.session;
    const std::string opened = session.document().scene.sourcePath;
    const std::string name = opened.empty() ? "untitled" : std::filesystem::path(opened).filename().string();
    EXPECT_EQ(session.windowTitle(), name + " - pathtracer");
    session.execute(setMaterial(session.document(), 0, edited(session, 0)));
    EXPECT_EQ(session.windowTitle(), "*" + name + " - pathtracer");
    session.save(test::testFolder() + "/titled.json");
    EXPECT_EQ(session.windowTitle(), "titled.json - pathtracer");
}

}  // namespace
}  // namespace pt::editor
