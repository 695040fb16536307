#pragma once
// EditorSession: the editor without a window. It holds the document, its undo history and a
// backend, turns edits into the least backend work (their SceneChanges), and renders. The
// window (editor/ui) drives it from two threads through RenderWorker; tests and the
// edit-latency figures of `pt-render bench` drive it directly, so what they measure is the
// editor's own path from an edit to a frame.
#include <atomic>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

#include "assets/color/color_processor.h"
#include "editor/command_stack.h"
#include "editor/picking.h"
#include "render/util/progress.h"
#include "render/util/stopwatch.h"

namespace pt::editor {

// What the last edit cost, from the command to the first frame that shows it.
struct EditLatency {
    std::string label;   // the command, e.g. "Edit material white"
    std::string action;  // what sync did: nothing / reset / materials / TLAS / refit / rebuild / full build
    double applySeconds = 0.0;  // the command writing the document (e.g. 10M new positions)
    double syncSeconds = 0.0;   // backend sync alone
    // Command handed to the session (execute, undo, redo) -> first pass of samples done:
    // apply, sync and the pass. Frames for display are timed from the same instant.
    double toFrameSeconds = 0.0;
    bool complete = false;  // false until that first frame exists
};

class EditorSession {
public:
    explicit EditorSession(std::unique_ptr<Backend> backend);

    // --- The document (the UI thread) ---
    // Replaces the document with the scene at `path`; on failure returns the loader's message
    // (naming the file and element) and keeps the current scene. "" on success.
    std::string open(const std::string& path, const ProgressFn& progress = {});
    // Takes a scene loaded elsewhere (e.g. on a loader thread) as the new document.
    void adopt(Scene scene);
    const Document& document() const { return doc_; }
    // Grows with every document adopted (open): frames carry the one they show (RenderWorker),
    // so the window never shows the previous scene's image as the new one's.
    uint64_t documentSerial() const { return documentSerial_; }
    // The render thread: the document the backend holds, as of the last sync that succeeded.
    uint64_t syncedDocument() const { return syncedDocument_; }
    // Grows with every edit that changes what is rendered (execute, undo, redo, a cancelled
    // drag; not display-only edits): frames carry the one their samples include (syncedEdit,
    // RenderWorker), so the window knows when an edit reaches the screen (ScreenLatency).
    uint64_t editSerial() const { return editSerial_; }
    // The render thread: editSerial() as of the last sync that succeeded.
    uint64_t syncedEdit() const { return syncedEdit_; }
    const CommandStack& history() const { return history_; }
    SceneDelta execute(std::unique_ptr<EditCommand> command);
    bool undo();
    bool redo();
    void endDrag() { history_.closeMerge(); }
    // The drag under way undone and forgotten (Esc during a gizmo drag); false where none is open.
    bool cancelDrag();
    // Renders at width x height without making that an edit (the editor's --size, or a render
    // that follows the viewport): saving writes the file's own resolution unless the user
    // changes the resolution afterwards.
    void overrideResolution(uint32_t width, uint32_t height);
    // Back to the resolution the override replaced (the viewport no longer followed).
    void restoreResolution();
    // Writes scene JSON (atomic); throws InputError naming the file.
    void save(const std::string& path);
    bool modified() const { return history_.modified(); }
    // The window's title: the document's file name ("untitled" for none), "*" before it while
    // edits are unsaved, then "- pathtracer".
    std::string windowTitle() const;

    // --- The backend (the render thread) ---
    // Brings the backend up to date with every edit since the last call. Returns the report;
    // a backend refusing the scene (e.g. BVH off over its budget) throws std::invalid_argument
    // and keeps its previous state.
    SyncReport sync(const ProgressFn& progress = {});
    const SceneDelta& pendingChanges() const { return pending_; }
    // Adds up to `passes` samples per pixel, stopping at the viewer's target spp. Returns the
    // passes rendered: 0 where an edit that restarts the accumulation (execute, undo, redo,
    // adopt) or interruptRender() stopped the pass under way, which a render thread's render()
    // watches for so that the edit waits for one sample (a wave on a GPU), not a whole pass (the
    // accumulation is then empty, as the edit's sync would leave it). sync() lowers the flag.
    uint32_t render(uint32_t passes) { return render(passes, doc_.viewer.targetSpp); }
    // The same, with the target given, for a render thread that must not read the document
    // while the UI thread edits it.
    uint32_t render(uint32_t passes, uint32_t targetSpp);
    // Any thread: stops a render() under way, as such an edit does (e.g. the window closing).
    void interruptRender() { interrupt_ = true; }
    // Off: render() always finishes its passes, as before interrupts (a benchmark's baseline).
    void setPassInterrupts(bool on);
    // The linear image the viewport shows: the beauty (aov -1; denoised with `denoise` once
    // its guides are accumulated) or that AOV, RGBA float.
    void readDisplayed(int32_t aov, bool denoise, std::vector<float>& rgba) const;
    // The beauty as readDisplayed gives it, written into device memory (CUDA-GL interop);
    // false where the backend cannot.
    bool copyDisplayedToDevice(bool denoise, void* deviceRgba) const;
    // Seconds the last denoise of a shown or exported frame took (0: none yet).
    double lastDenoiseSeconds() const { return lastDenoiseSeconds_.load(); }
    bool converged() const { return converged(doc_.viewer.targetSpp); }
    bool converged(uint32_t targetSpp) const;
    Backend& backend() { return *backend_; }
    const Backend& backend() const { return *backend_; }
    void setBackend(std::unique_ptr<Backend> backend);  // everything is synced again
    PickResult pick(float px, float py) { return editor::pick(*backend_, doc_.scene, px, py); }
    // Copies: the UI thread reads them while the render thread updates them.
    EditLatency lastEdit() const;
    SyncReport lastSync() const;

    // Writes the beauty as a layered EXR (assets/exr_layers.h: with the viewer's export AOVs
    // that the backend accumulates now, half or float as the viewer says) and/or as a
    // display-referred PNG/JPEG/TIFF through `display` (the viewport's: displayProcessorFor in
    // color_view.h), dithered as the viewer says; spp, render time, backend, scene, camera and
    // the view go in the metadata. Either path may be "" to skip that file. Returns the AOV
    // layers written; export AOVs not accumulated yet are left out.
    AovMask exportRender(const std::string& exrPath, const std::string& displayPath,
                         const DisplayProcessor& display) const;

private:
    // An edit handed over at `start` and applied now.
    void noteEdit(const std::string& label, const SceneDelta& changes, Clock::time_point start);

    // Whether `wanted` holds the denoiser's guides and the backend lacks one, or holds one that
    // started after the beauty.
    bool needsFreshGuides(AovMask wanted) const;
    // The render's size is the one overrideResolution set (not one the user set since).
    bool showsOverriddenResolution() const;
    // Whether the denoiser can run now: asked for and its guides accumulated with the beauty.
    bool denoises(bool asked) const { return asked && !needsFreshGuides(kDenoiseGuideAovs); }

    Document doc_;
    CommandStack history_;
    mutable std::atomic<double> lastDenoiseSeconds_{0.0};
    bool keepDenoiseGuides_ = false;  // accumulate the denoiser's guides (sync())
    std::unique_ptr<Backend> backend_;
    SceneDelta pending_ = SceneChanges::All;
    std::atomic<bool> interrupt_{false};  // the backend's interrupt flag (render())
    std::atomic<uint64_t> documentSerial_{0}, syncedDocument_{0}, editSerial_{0}, syncedEdit_{0};
    bool passInterrupts_ = true;
    std::vector<Material> materialsAtLoad_;
    RenderSettings fileRender_, overriddenRender_;
    bool resolutionOverridden_ = false;
    // Written by both threads (edits on the UI's, frames on the render thread's).
    mutable std::mutex statusMutex_;
    EditLatency lastEdit_;
    Clock::time_point editStart_{};
    SyncReport lastSync_;
};

}  // namespace pt::editor
