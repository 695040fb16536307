#pragma once
// EditorUi: the state the window's panels share (selection, dialogs, the queue of edits for the
// render thread) and the operations they call. Panels are free functions over it, one file each
// (outliner_panel.cpp, inspector_panel.cpp, ...), so each reads on its own.
#include <deque>
#include <functional>
#include <map>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "editor/animation_playback.h"
#include "editor/render_worker.h"
#include "editor/scene_load_job.h"
#include "editor/screen_latency.h"
#include "editor/ui/display_view.h"
#include "editor/ui/panel_layout.h"

struct GLFWwindow;

namespace pt::editor {

struct Selection {
    enum class Kind { None, Object, Instance, Light, Camera } kind = Kind::None;
    int32_t index = -1;     // objects, instances or lights index by kind
    int32_t instance = -1;  // the instance picked in the viewport (its materials are shown), or -1
};

struct CameraBookmark {
    std::string name;
    Camera camera;
};

// Command-line choices that shape the session (app/pathtracer/main.cpp).
struct EditorOptions {
    std::string scenePath;
    std::string backend;             // "" = cuda where usable, else cpu
    uint32_t width = 0, height = 0;  // --size; 0 = the scene's
    int64_t frames = -1;             // --frames N: exit after N frames with new samples
    std::string screenshotPath;      // --screenshot: written after --frames, and on F12
    std::string referencePath;       // --reference: an image to measure the error against
    std::string ocioPath;            // --ocio: an OpenColorIO config, over the scene's and $OCIO
    std::string latencyLogPath;      // --latency-log: edit-to-screen records as JSON lines
    bool frameWait = true;           // --no-frame-wait: swap without waiting for this frame's edits
    uint32_t spp = 0;                // --spp: stop accumulating there
};

class EditorUi {
public:
    EditorUi(EditorSession& session, RenderWorker& worker, const EditorOptions& options);

    EditorSession& session;
    RenderWorker& worker;
    const EditorOptions options;
    const Document& doc() const { return session.document(); }
    // The render's size follows the viewport's (ViewerSettings::followViewport), unless --size
    // fixed it.
    bool followsViewport() const { return options.width == 0 && doc().viewer.followViewport; }

    // Edits go through here: applied now when the render thread allows, else queued in order.
    void apply(std::unique_ptr<EditCommand> command);
    void endDrag();     // after ImGui::IsItemDeactivatedAfterEdit(): closes the undo step
    void cancelDrag();  // the open step undone and forgotten (Esc during a gizmo drag)
    // Duplicate (Ctrl+D): the copy beside the original as the camera sees it, and selected.
    void duplicateBeside(uint32_t object);
    void undo();
    void redo();
    void flushEdits();  // once per frame: applies what was queued

    // Files.
    // Asynchronous; errors end in a dialog. openScene asks first where the document has
    // unsaved edits; loadScene does not (the scene named on the command line).
    void openScene(const std::string& path);
    void loadScene(const std::string& path);
    void quit(GLFWwindow* window);  // closes it, asking first where edits are unsaved
    // Runs `action` (which would lose the document's unsaved edits: `what`, e.g. "Quitting")
    // at once where there are none, else once the user says so in the "Unsaved edits" dialog.
    void askBeforeDiscarding(const std::string& what, std::function<void()> action);
    // Takes a finished load; false when it failed (the error is queued for the dialog).
    bool pollLoad();
    void saveScene(const std::string& path, bool confirmedOverwrite);
    void exportRender(const std::string& exrPath, const std::string& pngPath);
    void switchBackend(const std::string& name);
    // Once a frame, `elapsed` wall seconds after the last: while the timeline plays, the
    // animated objects move to the playback's next time (an edit); true while it plays.
    bool tickAnimation(double elapsed);
    void showError(const std::string& message) { errors.push_back(message); }
    // A line in the status bar that needs no answer: what was saved or exported where, a
    // loaded scene's warnings.
    void notify(const std::string& message) { notice = message; }

    Selection selection;
    AnimationPlayback playback;  // the Animation panel's timeline
    std::vector<CameraBookmark> bookmarks;
    std::vector<std::string> recentFiles;
    std::vector<std::string> errors;      // shown one at a time in a modal dialog
    std::string notice;                   // the status bar's message (notify)
    Camera fileCamera;                    // the opened scene's camera, for Camera > Reset
    PanelLayout layout;                   // the panels' column (its width is the user's)
    std::string pendingOverwrite;         // a save path awaiting "replace?" confirmation
    std::string discardWhat;              // what the "Unsaved edits" dialog asks about
    std::function<void()> discardAction;  // what it runs once the user agrees
    std::unique_ptr<SceneLoadJob> loading;
    std::string backendName;
    BackendCapabilities backendCaps;  // of the backend that runs (render panel, interop)
    // The OpenColorIO config and view the viewport draws with, re-resolved when the scene's
    // color settings change (updateColorView, once a frame).
    ColorView colorView;
    void updateColorView();
    // The reference image (its path as typed) and what the viewport shows of it.
    std::string referencePath;
    CompareView compare = CompareView::Render;
    void loadReference(const std::string& path);
    bool showOpenDialog = false, showSaveDialog = false, showExportDialog = false;
    // Numbers the Stats panel shows.
    std::vector<float> frameMillis;  // UI frame times, most recent last
    DisplayFrame lastFrame;
    std::string framePath;        // how frames reach the screen, and why not by interop
    std::string glRenderer;       // GL_RENDERER, GL_VERSION: where the window draws
    ScreenLatency screenLatency;  // input to swapped frame, per edit (flushEdits, the frame loop)
    // Texture slots the user switched off, (material, slot) -> texture, so switching back on
    // restores them; cleared when another scene is opened.
    std::map<std::pair<uint32_t, int>, int32_t> switchedOffTextures;

private:
    // An edit for the session, with when the input behind it reached the window.
    struct QueuedEdit {
        std::function<void(EditorSession&)> change;
        ScreenLatency::Clock::time_point input;
    };
    void queue(std::function<void(EditorSession&)> change);
    std::deque<QueuedEdit> queued_;
    std::string colorRequest_;     // what colorView was resolved for
    double sinceShownPose_ = 0.0;  // wall seconds of playback since the last pose was applied
};

// The panels and menus (one file each).
void drawMainMenu(EditorUi& ui);
void drawOutliner(EditorUi& ui);
void drawInspector(EditorUi& ui);
void drawCameraPanel(EditorUi& ui);
void drawRenderPanel(EditorUi& ui);
void drawEnvironmentPanel(EditorUi& ui);
void drawDisplayPanel(EditorUi& ui, const DisplayView& view);
void drawAnimationPanel(EditorUi& ui);
void drawStatsPanel(EditorUi& ui);
// The main figures over the viewport's top right corner (PanelLayout::statsOverlay).
void drawStatsOverlay(EditorUi& ui, const ImageRect& image);
void drawDialogs(EditorUi& ui);
// The bar at the window's foot: the last notice, and the render's progress. It is a frame high
// (ImGui::GetFrameHeight(), as the menu bar), which the viewport leaves free.
void drawStatusBar(EditorUi& ui, float width, float height);

}  // namespace pt::editor
