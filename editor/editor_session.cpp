#include "editor/editor_session.h"

#include <algorithm>
#include <filesystem>
#include <stdexcept>

#include "assets/image/exr_layers.h"
#include "assets/image/image_write.h"
#include "assets/scene_loader.h"
#include "editor/scene_saving.h"

namespace pt::editor {

EditorSession::EditorSession(std::unique_ptr<Backend> backend) : backend_(std::move(backend)) {
    if (!backend_) throw std::invalid_argument("EditorSession needs a backend");
    setPassInterrupts(true);
    doc_.skinning = skinningSite(*backend_);
}

void EditorSession::setPassInterrupts(bool on) {
    passInterrupts_ = on;
    backend_->setInterruptFlag(on ? &interrupt_ : nullptr);
}

std::string EditorSession::open(const std::string& path, const ProgressFn& progress) {
    LoadResult loaded = loadScene(path, progress);
    if (!loaded.ok()) return loaded.error;
    adopt(std::move(*loaded.scene));
    return {};
}

void EditorSession::adopt(Scene scene) {
    doc_.scene = std::move(scene);
    // Exposure belongs to a scene's light levels: the last file's does not carry over (a sunlit
    // model opened after a dim room came up white).
    doc_.viewer.display.exposureStops = 0.0f;
    materialsAtLoad_ = materialParams(doc_.scene);
    resolutionOverridden_ = false;
    history_.clear();
    pending_ = SceneChanges::All;
    interrupt_ = true;
    ++documentSerial_;
    std::lock_guard<std::mutex> lock(statusMutex_);
    lastEdit_ = {};
}

void EditorSession::noteEdit(const std::string& label, const SceneDelta& changes, Clock::time_point start) {
    pending_ |= changes;
    if ((changes.mask & ~SceneChangeMask(SceneChanges::Display)) == 0) return;  // nothing to render again
    interrupt_ = true;  // the samples in flight are of the scene before the edit
    ++editSerial_;
    std::lock_guard<std::mutex> lock(statusMutex_);
    lastEdit_ = {};
    lastEdit_.label = label;
    lastEdit_.applySeconds = secondsSince(start);
    editStart_ = start;
}

SceneDelta EditorSession::execute(std::unique_ptr<EditCommand> command) {
    const auto start = Clock::now();  // the edit's latency includes its own apply
    const std::string label = command->label();
    const SceneDelta changes = history_.execute(doc_, std::move(command));
    noteEdit(label, changes, start);
    return changes;
}

bool EditorSession::undo() {
    if (!history_.canUndo()) return false;
    const auto start = Clock::now();
    const std::string label = "Undo " + history_.undoLabel();
    noteEdit(label, history_.undo(doc_), start);
    return true;
}

bool EditorSession::cancelDrag() {
    const auto start = Clock::now();
    const std::string label = "Cancel " + history_.undoLabel();
    const size_t depth = history_.undoDepth();
    const SceneDelta changes = history_.cancelMerge(doc_);
    if (history_.undoDepth() == depth) return false;
    noteEdit(label, changes, start);
    return true;
}

bool EditorSession::redo() {
    if (!history_.canRedo()) return false;
    const auto start = Clock::now();
    const std::string label = "Redo " + history_.redoLabel();
    noteEdit(label, history_.redo(doc_), start);
    return true;
}

void EditorSession::overrideResolution(uint32_t width, uint32_t height) {
    // The file's own size, as it was before the first override (a viewport that follows the
    // window overrides again at every resize), or as the user last set it.
    if (!showsOverriddenResolution()) fileRender_ = doc_.scene.render;
    doc_.scene.render.width = width;
    doc_.scene.render.height = height;
    overriddenRender_ = doc_.scene.render;
    resolutionOverridden_ = true;
    pending_ |= SceneChanges::Settings;
    interrupt_ = true;
}

bool EditorSession::showsOverriddenResolution() const {
    const RenderSettings& render = doc_.scene.render;
    return resolutionOverridden_ && render.width == overriddenRender_.width &&
           render.height == overriddenRender_.height;
}

void EditorSession::restoreResolution() {
    if (!showsOverriddenResolution()) return;  // not overridden, or set by the user since
    RenderSettings& render = doc_.scene.render;
    render.width = fileRender_.width;
    render.height = fileRender_.height;
    resolutionOverridden_ = false;
    pending_ |= SceneChanges::Settings;
    interrupt_ = true;
}

std::string EditorSession::windowTitle() const {
    const std::string& source = doc_.scene.sourcePath;
    const std::string name = source.empty() ? "untitled" : std::filesystem::path(source).filename().string();
    return (modified() ? "*" : "") + name + " - pathtracer";
}

void EditorSession::save(const std::string& path) {
    RenderSettings& render = doc_.scene.render;
    const RenderSettings shown = render;
    const bool restore = showsOverriddenResolution();
    if (restore) {
        render.width = fileRender_.width;
        render.height = fileRender_.height;
    }
    try {
        saveSceneJson(doc_.scene, materialsAtLoad_, path);
    } catch (...) {
        render = shown;
        throw;
    }
    render = shown;
    history_.markSaved();
    // The document is that file now: exports name it, and saving again needs no confirmation.
    doc_.scene.sourcePath = std::filesystem::absolute(path).lexically_normal().string();
}

SyncReport EditorSession::sync(const ProgressFn& progress) {
    SceneDelta changes = pending_.without(SceneChanges::Display);
    pending_ = SceneChanges::None;
    interrupt_ = false;  // the edits that raised it are applied now
    const uint64_t document = documentSerial_, edit = editSerial_;  // edits wait for the sync
    // Only the AOV on screen and the export layers are accumulated (the others are not even
    // allocated).
    const int32_t aov = doc_.viewer.aov;
    const AovMask shown = aov >= 0 && aov < int32_t(Aov::Count) ? aovBit(Aov(aov)) : 0u;
    // The denoiser's guides while it is on; once it is off they stay (turning it off is a
    // display change) until an edit restarts the accumulation anyway.
    if (changes.mask != SceneChanges::None || doc_.viewer.denoise) keepDenoiseGuides_ = doc_.viewer.denoise;
    const AovMask guides = keepDenoiseGuides_ ? kDenoiseGuideAovs : 0u;
    const AovMask layers = shown | (doc_.viewer.exportAovs & kAllAovs);
    const AovMask wanted = layers | guides;
    // Guides alone settle and stop (kSettledGuideSamples); what the user looks at or exports
    // accumulates in full.
    backend_->setAovSampleCap(settledGuideCap(layers));
    if (backend_->aovs() != wanted) {
        if (changes.mask == SceneChanges::None && !needsFreshGuides(wanted)) {
            backend_->changeAovs(wanted);  // a display change: the beauty keeps its samples
        } else {
            backend_->setAovs(wanted);  // from the reset that follows
            changes |= SceneChanges::Settings;
        }
    }
    if (changes.mask == SceneChanges::None) {
        syncedDocument_ = document;
        syncedEdit_ = edit;
        return {"nothing", 0.0, 0.0, {}};
    }
    if (changes.has(SceneChanges::Settings)) backend_->setToggles(doc_.toggles);
    SyncReport report;
    try {
        report = backend_->sync(doc_.scene, changes, progress);
    } catch (...) {
        pending_ |= changes;  // still owed: the next sync tries again (e.g. after an undo)
        throw;
    }
    syncedDocument_ = document;
    syncedEdit_ = edit;
    std::lock_guard<std::mutex> lock(statusMutex_);
    lastSync_ = report;
    lastEdit_.action = report.action;
    lastEdit_.syncSeconds = report.seconds;
    return report;
}

// The denoiser's guides must hold every sample of the beauty or the cap's (requireDenoiseGuides):
// turning it on restarts the accumulation once, unless they happen to be there already.
bool EditorSession::needsFreshGuides(AovMask wanted) const {
    return (wanted & kDenoiseGuideAovs) == kDenoiseGuideAovs && !denoiseGuidesComplete(*backend_);
}

bool EditorSession::converged(uint32_t target) const {
    return target > 0 && backend_->stats().samplesPerPixel >= target;
}

void EditorSession::readDisplayed(int32_t aov, bool denoise, std::vector<float>& rgba) const {
    if (aov >= 0 && (backend_->aovs() & aovBit(Aov(aov)))) {
        backend_->readAov(Aov(aov), rgba);
    } else if (denoises(denoise)) {
        lastDenoiseSeconds_ = backend_->readDenoised(rgba);
    } else {
        backend_->readBeauty(rgba);
    }
}

bool EditorSession::copyDisplayedToDevice(bool denoise, void* deviceRgba) const {
    if (!denoises(denoise)) return backend_->copyBeautyToDevice(deviceRgba);
    double seconds = 0.0;
    const bool copied = backend_->copyDenoisedToDevice(deviceRgba, &seconds);
    if (copied) lastDenoiseSeconds_ = seconds;
    return copied;
}

EditLatency EditorSession::lastEdit() const {
    std::lock_guard<std::mutex> lock(statusMutex_);
    return lastEdit_;
}

SyncReport EditorSession::lastSync() const {
    std::lock_guard<std::mutex> lock(statusMutex_);
    return lastSync_;
}

uint32_t EditorSession::render(uint32_t passes, uint32_t target) {
    const uint32_t done = backend_->stats().samplesPerPixel;
    if (target > 0) passes = done >= target ? 0 : std::min(passes, target - done);
    if (passes == 0) return 0;
    backend_->render(passes);
    if (backend_->stats().samplesPerPixel != done + passes) return 0;  // interrupted (render())
    std::lock_guard<std::mutex> lock(statusMutex_);
    // The edit's first frame is the first pass after its sync (which names its action), not a
    // pass of the scene before it that was in flight when the edit came (render thread).
    if (!lastEdit_.complete && !lastEdit_.label.empty() && !lastEdit_.action.empty()) {
        lastEdit_.toFrameSeconds = secondsSince(editStart_);
        lastEdit_.complete = true;
    }
    return passes;
}

void EditorSession::setBackend(std::unique_ptr<Backend> backend) {
    if (!backend) throw std::invalid_argument("setBackend: no backend");
    backend_ = std::move(backend);
    setPassInterrupts(passInterrupts_);
    doc_.skinning = skinningSite(*backend_);
    // A backend that reads the host's vertices must not see those a GPU skin left behind.
    if (doc_.skinning == SkinningSite::Host) skinPendingOnHost(doc_.scene);
    pending_ = SceneChanges::All;
}

AovMask EditorSession::exportRender(const std::string& exrPath, const std::string& displayPath,
                                    const DisplayProcessor& display) const {
    std::vector<float> beauty;  // what the viewport shows
    readDisplayed(-1, doc_.viewer.denoise, beauty);
    const BackendStats stats = backend_->stats();
    ImageMetadata metadata = renderMetadata(stats.samplesPerPixel, std::to_string(stats.renderSeconds),
                                            backend_->name(), doc_.scene.sourcePath, "pathtracer editor 0.1");
    const ImageMetadata view = displayMetadata(display, doc_.viewer.display.dither);
    metadata.insert(metadata.end(), view.begin(), view.end());
    const uint32_t w = backend_->width(), h = backend_->height();
    AovMask written = 0;
    if (!exrPath.empty()) {
        const ViewerSettings& viewer = doc_.viewer;
        LayeredExr exr = layeredExr(readRenderedImages(*backend_, viewer.exportAovs),
                                    viewer.exportHalf ? ExrPixelType::Half : ExrPixelType::Float,
                                    doc_.scene.camera, metadata);
        if (denoises(viewer.denoise)) exr.denoised = beauty;  // beside the raw beauty
        writeLayeredExr(exrPath, exr);
        for (const AovImage& layer : exr.aovs) written |= aovBit(layer.aov);
    }
    if (!displayPath.empty()) {
        writeDisplayImage(displayPath, w, h, display.encode8(beauty, w, doc_.viewer.display.dither),
                          metadata);
    }
    return written;
}

}  // namespace pt::editor
