#include "editor/ui/editor_ui.h"

#include <GLFW/glfw3.h>

#include <filesystem>

#include "assets/input_error.h"
#include "editor/animation_edits.h"
#include "editor/object_edits.h"
#include "editor/ui/input_events.h"
#include "editor/ui/recent_files.h"

namespace pt::editor {

namespace fs = std::filesystem;

EditorUi::EditorUi(EditorSession& s, RenderWorker& w, const EditorOptions& o)
    : session(s), worker(w), options(o), recentFiles(loadRecentFiles()) {}

void EditorUi::queue(std::function<void(EditorSession&)> change) {
    const auto now = ScreenLatency::Clock::now();
    queued_.push_back({std::move(change), inputEvents().firstEventTime().value_or(now)});
    flushEdits();
}

void EditorUi::flushEdits() {
    while (!queued_.empty()) {
        QueuedEdit& next = queued_.front();
        uint64_t edit = 0;
        std::string label;
        const bool applied = worker.tryEdit([&](EditorSession& s) {
            const uint64_t before = s.editSerial();
            next.change(s);
            if (s.editSerial() == before) return;  // nothing to render again (a display change)
            edit = s.editSerial();
            label = s.lastEdit().label;
        });
        if (!applied) return;  // the render thread is syncing: next frame
        if (edit > 0)
            screenLatency.editApplied(edit, std::move(label), next.input, ScreenLatency::Clock::now());
        queued_.pop_front();
    }
}

void EditorUi::apply(std::unique_ptr<EditCommand> command) {
    // std::function needs a copyable callable; the command itself runs once.
    auto held = std::make_shared<std::unique_ptr<EditCommand>>(std::move(command));
    queue([held](EditorSession& s) { s.execute(std::move(*held)); });
}

void EditorUi::endDrag() {
    queue([](EditorSession& s) { s.endDrag(); });
}

void EditorUi::cancelDrag() {
    queue([](EditorSession& s) { s.cancelDrag(); });
}

void EditorUi::duplicateBeside(uint32_t object) {
    const int32_t copy = int32_t(doc().scene.objects.size());
    apply(duplicateObject(doc(), object, duplicateOffset(doc().scene, object)));
    selection = {Selection::Kind::Object, copy, -1};
}

void EditorUi::undo() {
    queue([](EditorSession& s) { s.undo(); });
}

void EditorUi::redo() {
    queue([](EditorSession& s) { s.redo(); });
}

void EditorUi::openScene(const std::string& path) {
    askBeforeDiscarding("Opening " + path, [this, path] { loadScene(path); });
}

void EditorUi::quit(GLFWwindow* window) {
    askBeforeDiscarding("Quitting", [window] { glfwSetWindowShouldClose(window, GLFW_TRUE); });
}

void EditorUi::loadScene(const std::string& path) {
    if (loading) {
        showError("Still loading " + loading->path() + "; open " + path + " afterwards.");
        return;
    }
    loading = std::make_unique<SceneLoadJob>(path);
}

bool EditorUi::pollLoad() {
    if (!loading || !loading->done()) return true;
    const std::string path = loading->path();
    LoadResult result = loading->take();
    loading.reset();
    if (!result.ok()) {
        showError(result.error);  // the current scene stays
        return false;
    }
    Scene scene = std::move(*result.scene);
    // Warnings need no answer: the status bar says them (a model without lights used to stop
    // everything with a dialog to say that it is lit by a white environment).
    std::string warnings;
    for (const std::string& warning : scene.warnings)
        warnings += (warnings.empty() ? "Warning: " : "; ") + warning;
    notify(warnings.empty() ? "Opened " + path : warnings);
    fileCamera = scene.camera;
    queued_.clear();
    screenLatency.forget();
    worker.edit([&](EditorSession& s) {
        s.adopt(std::move(scene));
        if (options.width > 0 && options.height > 0) s.overrideResolution(options.width, options.height);
    });
    selection = {};
    bookmarks.clear();
    switchedOffTextures.clear();
    recentFiles = rememberRecentFile(recentFiles, fs::absolute(path).string());
    return true;
}

void EditorUi::askBeforeDiscarding(const std::string& what, std::function<void()> action) {
    if (!session.modified()) {
        action();
        return;
    }
    discardWhat = what;
    discardAction = std::move(action);
}

void EditorUi::saveScene(const std::string& path, bool confirmedOverwrite) {
    const std::string current = doc().scene.sourcePath;
    std::error_code ec;
    const bool sameFile = !current.empty() && fs::exists(path) && fs::equivalent(path, current, ec);
    if (!confirmedOverwrite && fs::exists(path) && !sameFile) {
        pendingOverwrite = path;  // drawDialogs asks first
        return;
    }
    flushEdits();
    try {
        worker.edit([&](EditorSession& s) { s.save(path); });
        recentFiles = rememberRecentFile(recentFiles, fs::absolute(path).string());
        notify("Saved " + path);
    } catch (const std::exception& e) {
        showError(e.what());
    }
}

void EditorUi::exportRender(const std::string& exrPath, const std::string& pngPath) {
    try {
        const DisplayProcessor display = displayProcessorFor(colorView, doc().viewer);
        worker.withBackend([&](EditorSession& s) { s.exportRender(exrPath, pngPath, display); });
        notify("Exported " + exrPath + (exrPath.empty() || pngPath.empty() ? "" : " and ") + pngPath);
    } catch (const std::exception& e) {
        showError(e.what());
    }
}

void EditorUi::updateColorView() {
    const ColorSettings& c = doc().scene.color;
    const std::string request =
        options.ocioPath + "\n" + c.config + "\n" + c.display + "\n" + c.view + "\n" + c.look;
    if (request == colorRequest_) return;
    colorRequest_ = request;
    colorView = resolveColorView(options.ocioPath, c, colorView);
}

void EditorUi::loadReference(const std::string& path) {
    try {
        worker.errors().load(path);
        referencePath = path;
    } catch (const std::exception& e) {
        showError(e.what());
    }
}

bool EditorUi::tickAnimation(double elapsed) {
    if (!playback.playing()) return false;
    // The next pose waits until the last one has been seen (its first sample done): a backend
    // slower than the UI skips animation time, rather than restarting its pass every UI frame
    // and never showing one.
    sinceShownPose_ += elapsed;
    if (!session.lastEdit().complete) return true;
    elapsed = sinceShownPose_;
    sinceShownPose_ = 0.0;
    const float time = shownTime(doc().scene);
    const float next = playback.advance(time, shownDuration(doc().scene), elapsed);
    if (next != time) apply(setAnimationTime(doc(), next));
    // Playback is one undo step, closed when it stops.
    if (!playback.playing()) endDrag();
    return playback.playing();
}

void EditorUi::switchBackend(const std::string& name) {
    try {
        std::unique_ptr<Backend> next = createBackend(name);
        const BackendCapabilities caps = next->capabilities();
        session.interruptRender();  // the old backend's samples are thrown away anyway
        worker.withBackend(
            [&](EditorSession& s) { worker.edit([&](EditorSession&) { s.setBackend(std::move(next)); }); });
        backendName = name;
        backendCaps = caps;
    } catch (const std::exception& e) {
        showError(e.what());
    }
}

}  // namespace pt::editor
