#include "editor/ui/editor_window.h"

#include <imgui.h>
#include <imgui_impl_glfw.h>
#include <imgui_impl_opengl3.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <optional>

#include "editor/scene_edits.h"
#include "editor/selection_box.h"
#include "editor/ui/background_render_threads.h"
#include "editor/ui/gl.h"
#include "editor/ui/input_events.h"
#include "editor/ui/interop_frame.h"
#include "editor/ui/latency_log.h"
#include "editor/ui/panel_layout.h"
#include "editor/ui/redraw_policy.h"
#include "editor/ui/screenshot.h"
#include "editor/ui/viewport_input.h"
#include "editor/ui/viewport_toolbar.h"
#include "editor/viewport_resolution.h"
#include "render/util/stopwatch.h"

namespace pt::editor {
namespace {

constexpr const char* kScreenshotName = "pathtracer-screenshot.png";  // F12 without --screenshot
constexpr size_t kFrameHistory = 120;

// Files dropped on the window, collected by GLFW's callback and opened by the frame loop.
std::vector<std::string>& droppedFiles() {
    static std::vector<std::string> files;
    return files;
}

// The window's close button quits as File > Quit does: with unsaved edits the window stays
// until the user answers.
void onCloseRequest(GLFWwindow* window) {
    auto* ui = static_cast<EditorUi*>(glfwGetWindowUserPointer(window));
    if (!ui) return;
    glfwSetWindowShouldClose(window, GLFW_FALSE);
    ui->quit(window);
}

void onDrop(GLFWwindow*, int count, const char** paths) {
    for (int i = 0; i < count; ++i) droppedFiles().push_back(paths[i]);
}

std::string glString(GLenum name) {
    const GLubyte* text = glGetString(name);
    return text ? reinterpret_cast<const char*>(text) : "(unknown)";
}

std::string chooseBackend(const std::string& requested) {
    return requested.empty() ? defaultBackendName() : requested;
}

// The numbered path of the n-th F12 screenshot: shot.png, shot-1.png, shot-2.png, ...
std::string screenshotPath(const std::string& base, int n) {
    if (n == 0) return base;
    std::filesystem::path p(base);
    return (p.parent_path() / (p.stem().string() + "-" + std::to_string(n) + p.extension().string()))
        .string();
}

// Panel `index` of kPanelNames, where it is (the column or its own window).
void drawPanel(EditorUi& ui, const DisplayView& view, int index) {
    switch (index) {
        case 0: drawOutliner(ui); break;
        case 1: drawInspector(ui); break;
        case 2: drawCameraPanel(ui); break;
        case 3: drawRenderPanel(ui); break;
        case 4: drawEnvironmentPanel(ui); break;
        case 5: drawDisplayPanel(ui, view); break;
        case 6: drawAnimationPanel(ui); break;
        default: drawStatsPanel(ui); break;
    }
}

// Panels taken out of the column (Window menu): each a window the user moves and sizes, first
// placed over the viewport's left, staggered; its close button puts it back in the column.
void drawFloatingPanels(EditorUi& ui, const DisplayView& view) {
    const float s = ui.layout.scale;
    for (int i = 0; i < kPanelCount; ++i) {
        if (!ui.layout.floats(kPanelNames[i])) continue;
        ImGui::SetNextWindowPos(ImVec2((40.0f + 30.0f * float(i)) * s, (60.0f + 30.0f * float(i)) * s),
                                ImGuiCond_FirstUseEver);
        ImGui::SetNextWindowSize(ImVec2(380.0f * s, 420.0f * s), ImGuiCond_FirstUseEver);
        bool open = true;
        if (ImGui::Begin(kPanelNames[i], &open)) drawPanel(ui, view, i);
        ImGui::End();
        if (!open) ui.layout.setFloating(kPanelNames[i], false);
    }
}

// The panels' column at the window's right, `height` tall below the menu bar; dragging its left
// edge resizes it (remembered when the editor closes: panel_layout.h). The drag starts where the
// press was (InputEvents), not where the pointer is when a slow frame looks.
void drawPanels(EditorUi& ui, const DisplayView& view, float width, float height) {
    const float top = ImGui::GetFrameHeight();
    const float panelWidth = ui.layout.clampedWidth(width), edgeX = width - panelWidth;
    constexpr float kGrab = 4.0f;  // pixels either side of the edge
    const ImGuiIO& io = ImGui::GetIO();
    if (const std::optional<ScreenPoint> at = inputEvents().pressed(GLFW_MOUSE_BUTTON_LEFT);
        at && std::fabs(at->x - edgeX) <= kGrab && at->y > top && at->y < height) {
        ui.layout.resizing = true;
    }
    if (ui.layout.resizing && !ImGui::IsMouseDown(ImGuiMouseButton_Left) &&
        !inputEvents().pressed(GLFW_MOUSE_BUTTON_LEFT))
        ui.layout.resizing = false;
    if (ui.layout.resizing) ui.layout.width = width - io.MousePos.x;
    const bool overEdge =
        std::fabs(io.MousePos.x - edgeX) <= kGrab && io.MousePos.y > top && io.MousePos.y < height;
    if (overEdge || ui.layout.resizing) ImGui::SetMouseCursor(ImGuiMouseCursor_ResizeEW);
    // The edge's strip is a window of its own, so that pressing it is not a click in the viewport.
    ImGui::SetNextWindowPos(ImVec2(edgeX - kGrab, top));
    ImGui::SetNextWindowSize(ImVec2(2.0f * kGrab, height - top));
    ImGui::Begin("##panel edge", nullptr,
                 ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_NoBackground |
                     ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoMove);
    ImGui::End();
    ImGui::SetNextWindowPos(ImVec2(width - panelWidth, top));
    ImGui::SetNextWindowSize(ImVec2(panelWidth, height - top));
    ImGui::Begin("Panels", nullptr,
                 ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoTitleBar |
                     ImGuiWindowFlags_NoCollapse);
    for (int i = 0; i < kPanelCount; ++i) {
        if (!ui.layout.floats(kPanelNames[i])) drawPanel(ui, view, i);
    }
    ImGui::End();
    drawFloatingPanels(ui, view);
}

// The render's size, where it follows the viewport (viewport_resolution.h): the viewport's
// framebuffer pixels `width` x `height`. Without the render thread's lock (a sync under way),
// the change waits for a later frame.
void followViewport(EditorUi& ui, ViewportResolution& resolution, float width, float height,
                    bool navigating) {
    if (!ui.followsViewport()) {  // turned off: back to the scene's resolution
        if (resolution.following() && ui.worker.tryEdit([](EditorSession& s) { s.restoreResolution(); }))
            resolution.stop();
        return;
    }
    const RenderSettings& render = ui.doc().scene.render;
    const std::optional<RenderSize> size =
        resolution.update(width, height, ui.doc().viewer.resolutionScale, navigating,
                          {render.width, render.height}, glfwGetTime());
    if (size) ui.worker.tryEdit([&](EditorSession& s) { s.overrideResolution(size->width, size->height); });
}

// The selection's world box (selection_box.h), kept until the selection or the document
// changes: finding it walks the selected meshes' vertices, too much for every frame.
class SelectionOutline {
public:
    const std::optional<WorldBox>& box(const EditorUi& ui) {
        const Selection& sel = ui.selection;
        const uint64_t document = ui.session.documentSerial(), revision = ui.session.history().revision();
        if (sel.kind != kind_ || sel.index != index_ || document != document_ || revision != revision_) {
            kind_ = sel.kind;
            index_ = sel.index;
            document_ = document;
            revision_ = revision;
            const bool object = kind_ == Selection::Kind::Object,
                       instance = kind_ == Selection::Kind::Instance;
            box_ = object || instance
                       ? selectionBounds(ui.doc().scene, object ? index_ : -1, instance ? index_ : -1)
                       : std::nullopt;
        }
        return box_;
    }

private:
    Selection::Kind kind_ = Selection::Kind::None;
    int32_t index_ = -1;
    uint64_t document_ = ~uint64_t(0), revision_ = ~uint64_t(0);
    std::optional<WorldBox> box_;
};

// The selection's outline over the image, from the render's pixels to where the image lies in
// the window.
void drawSelectionOutline(const EditorUi& ui, SelectionOutline& outline, const ImageRect& image) {
    const std::optional<WorldBox>& box = outline.box(ui);
    if (!box || image.imageWidth == 0) return;
    const std::vector<ImageSegment> edges =
        boxInImage(*box, ui.doc().scene.camera, image.imageWidth, image.imageHeight);
    const float sx = image.width / float(image.imageWidth), sy = image.height / float(image.imageHeight);
    ImDrawList* draw = ImGui::GetBackgroundDrawList();
    draw->PushClipRect(ImVec2(image.x, image.y), ImVec2(image.x + image.width, image.y + image.height), true);
    for (const ImageSegment& e : edges) {
        draw->AddLine(ImVec2(image.x + e.a.x * sx, image.y + e.a.y * sy),
                      ImVec2(image.x + e.b.x * sx, image.y + e.b.y * sy), IM_COL32(255, 160, 40, 220), 1.5f);
    }
    draw->PopClipRect();
}

// In the middle of an empty viewport (a scene loading, or its BVH building before its first
// frame): what is under way.
void drawViewportStatus(EditorUi& ui, float width, float height) {
    const WorkerStatus status = ui.worker.status();
    std::string text = "Preparing the scene";
    if (ui.loading) {
        text = "Loading " + ui.loading->path();
    } else if (!status.stage.empty()) {
        text = status.stage + " (" + std::to_string(int(status.fraction * 100.0)) + "%)";
    } else if (!status.error.empty()) {
        text = status.error;
    }
    const ImVec2 size = ImGui::CalcTextSize(text.c_str());
    ImGui::GetBackgroundDrawList()->AddText(ImVec2(0.5f * (width - size.x), 0.3f * height),
                                            IM_COL32(200, 200, 200, 255), text.c_str());
}

class Window {
public:
    explicit Window(const EditorOptions& o) {
        if (!glfwInit())
            throw std::runtime_error(
                "cannot initialise GLFW (is there a display? DISPLAY is unset or unusable)");
        glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 3);
        glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 3);
        glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
        glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
        // Room for the render at its size (at least 640 square) beside the panels, between the
        // menu bar and the status bar.
        const int w = int(std::max(o.width, 640u) + uint32_t(PanelLayout::kDefaultWidth));
        const int h = int(std::max(o.height, 640u) + 40u);
        handle = glfwCreateWindow(w, h, "pathtracer", nullptr, nullptr);
        if (!handle) {
            glfwTerminate();
            throw std::runtime_error("cannot open an OpenGL 3.3 core window");
        }
        glfwMakeContextCurrent(handle);
        glfwSwapInterval(1);
        glfwSetDropCallback(handle, onDrop);
        installInputCallbacks(handle);  // before ImGui's callbacks, which chain to them
        IMGUI_CHECKVERSION();
        ImGui::CreateContext();
        ImGui::GetIO().IniFilename = nullptr;  // a fixed layout: no imgui.ini littering the working folder
        ImGui::StyleColorsDark();
        // A high-DPI screen: the font drawn at its pixel size (not a blurred scale of 13 px),
        // and every padding and size with it.
        float xscale = 1.0f, yscale = 1.0f;
        glfwGetWindowContentScale(handle, &xscale, &yscale);
        scale = std::clamp(std::max(xscale, yscale), 1.0f, 4.0f);
        if (scale > 1.0f) {
            ImFontConfig font;
            font.SizePixels = std::round(13.0f * scale);
            ImGui::GetIO().Fonts->AddFontDefault(&font);
            ImGui::GetStyle().ScaleAllSizes(scale);
        }
        ImGui_ImplGlfw_InitForOpenGL(handle, true);
        ImGui_ImplOpenGL3_Init("#version 330 core");
    }
    ~Window() {
        ImGui_ImplOpenGL3_Shutdown();
        ImGui_ImplGlfw_Shutdown();
        ImGui::DestroyContext();
        glfwDestroyWindow(handle);
        glfwTerminate();
    }
    GLFWwindow* handle = nullptr;
    float scale = 1.0f;  // the interface's, from the screen's content scale
};

// A new frame on screen: through CUDA-GL interop for the CUDA backend's beauty where the GL
// allows it, else from the frame's host copy.
void showFrame(EditorUi& ui, DisplayView& view, InteropFrame& interop) {
    const DisplayFrame& frame = ui.lastFrame;
    const bool device = ui.backendCaps.deviceFrames && frame.aov < 0;
    if (!frame.rgba.empty()) view.upload(frame);
    bool onGpu = false;
    if (device) {
        view.prepareDeviceFrame(frame);
        onGpu = interop.update(ui.worker, view.texture(), frame.width, frame.height);
        // Without interop the next frames must bring their pixels; with it they need not.
        ui.worker.setHostFrames(!onGpu);
    }
    ui.framePath = onGpu    ? "CUDA-GL interop (no host copy)"
                   : device ? std::string("host upload: ") + interop.why()
                            : "host upload";
}

// The frame just swapped shows edits that were waiting for the screen: it is finished first
// (the swap only queued it), so the time read is when a user sees it.
void noteSwap(EditorUi& ui, LatencyLog& log) {
    const DisplayFrame& frame = ui.lastFrame;
    const uint32_t spp = frame.stats.samplesPerPixel;
    if (!ui.screenLatency.resolves(frame.edit, spp) && !log.waitsForFirstFrame(frame.document, spp)) return;
    glFinish();
    const auto swapped = ScreenLatency::Clock::now();
    log.frameSwapped(frame.document, spp, ui.framePath, swapped);
    const std::vector<ScreenLatencyRecord> shown = ui.screenLatency.frameSwapped(frame.edit, spp, swapped);
    if (shown.empty() || !log.on()) return;
    // What the log adds to each record, once for the frame.
    const std::string action = ui.session.lastSync().action;
    const double uiFrameMillis = medianOf({ui.frameMillis.begin(), ui.frameMillis.end()});
    for (const ScreenLatencyRecord& r : shown) log.edit(r, action, ui.framePath, uiFrameMillis);
}

// How long the window waits for the first samples of an edit made in the frame it is drawing. A
// GPU backend has them within a few milliseconds (sync, one pass, publish), and waiting puts
// them in this frame's swap instead of the next one's, a whole refresh later. A backend slower
// than this (the CPU's) is not waited for: every frame of a drag would be that much longer.
constexpr double kEditFrameWait = 0.008;

// The edits of this frame (the serial went past `editsBefore`) reach this frame's swap where the
// backend is quick enough; true when a new frame was shown.
bool showThisFramesEdits(EditorUi& ui, DisplayView& view, InteropFrame& interop, uint64_t editsBefore) {
    const uint64_t edit = ui.session.editSerial();
    if (edit <= editsBefore || ui.lastFrame.edit >= edit) return false;
    const double secondsPerPass = ui.worker.status().secondsPerPass;
    if (!(secondsPerPass > 0.0) || secondsPerPass > kEditFrameWait) return false;
    DisplayFrame frame;
    if (!ui.worker.waitForFrame(edit, kEditFrameWait) || !ui.worker.takeFrame(frame)) return false;
    if (frame.document != ui.session.documentSerial()) return false;
    ui.lastFrame = std::move(frame);
    showFrame(ui, view, interop);
    return true;
}

int frameLoop(Window& window, EditorUi& ui, const EditorOptions& options, LatencyLog& latencyLog) {
    DisplayView view;
    InteropFrame interop;
    ViewportInput input;
    ImageRect image;
    int64_t renderedFrames = 0;
    int screenshots = 0;
    auto last = Clock::now();
    glfwSetWindowUserPointer(window.handle, &ui);
    glfwSetWindowCloseCallback(window.handle, onCloseRequest);
    std::string title;  // on the window now
    DisplayFrame taken;
    ViewportResolution resolution;
    SelectionOutline outline;
    RedrawPolicy redraw;
    double wait = 0.0;  // the policy's answer after the last frame
    uint64_t eventsSeen = 0;
    while (!glfwWindowShouldClose(window.handle)) {
        if (wait == 0.0)
            glfwPollEvents();
        else if (wait == RedrawPolicy::kForever)
            glfwWaitEvents();
        else
            glfwWaitEventsTimeout(wait);
        FrameActivity activity;
        activity.happened = inputEvents().count() != eventsSeen || !droppedFiles().empty();
        eventsSeen = inputEvents().count();
        const float dt = float(secondsSince(last));
        last = Clock::now();
        ui.frameMillis.push_back(dt * 1e3f);
        if (ui.frameMillis.size() > kFrameHistory) ui.frameMillis.erase(ui.frameMillis.begin());
        for (const std::string& path : droppedFiles()) ui.openScene(path);
        droppedFiles().clear();
        if (!ui.pollLoad() && options.frames >= 0) {
            std::fprintf(stderr, "pathtracer: %s\n",
                         ui.errors.empty() ? "load failed" : ui.errors.front().c_str());
            return 1;  // automation: a scene that does not load is a failure, not a dialog
        }
        const uint64_t editsBefore = ui.session.editSerial();
        // A playing timeline draws every frame: each is a new pose.
        activity.happened |= ui.tickAnimation(dt);
        ui.flushEdits();
        if (std::string now = ui.session.windowTitle(); now != title) {
            title = std::move(now);
            glfwSetWindowTitle(window.handle, title.c_str());
            activity.happened = true;
        }
        // Frames of the document before an open are dropped, and so is the image on screen:
        // the viewport says what is under way until the new scene's first frame.
        const uint64_t document = ui.session.documentSerial();
        bool newFrame = false;
        if (ui.worker.takeFrame(taken)) {
            activity.happened = true;
            if (taken.document == document) {
                ui.lastFrame = std::move(taken);
                showFrame(ui, view, interop);
                newFrame = true;
                if (ui.lastFrame.stats.samplesPerPixel > 0) ++renderedFrames;
            }
        }
        if (ui.lastFrame.document != document) view.clear();
        ImGui_ImplOpenGL3_NewFrame();
        ImGui_ImplGlfw_NewFrame();
        ImGui::NewFrame();
        // A fly step covers the frame's time, but not the wait before it: after an idle wait
        // the first step would jump (frames follow each other while flying).
        const bool screenshot = input.handle(ui, image, std::min(dt, 0.05f));
        drawMainMenu(ui);
        int fbw = 0, fbh = 0, ww = 0, wh = 0;
        glfwGetFramebufferSize(window.handle, &fbw, &fbh);
        glfwGetWindowSize(window.handle, &ww, &wh);
        // The viewport: below the menu bar, left of the panels, above the status bar.
        const float top = ImGui::GetFrameHeight(), scale = ww > 0 ? float(fbw) / float(ww) : 1.0f;
        const float viewWidth = float(ww) - ui.layout.clampedWidth(float(ww)),
                    viewHeight = float(wh) - top - top;
        followViewport(ui, resolution, viewWidth * scale, viewHeight * scale, input.moving());
        drawPanels(ui, view, float(ww), float(wh) - top);  // the status bar is a frame high, as the menu bar
        drawStatusBar(ui, float(ww), float(wh));
        if (!view.hasImage()) {
            drawViewportStatus(ui, viewWidth, viewHeight);
        } else {
            drawSelectionOutline(ui, outline, image);
            input.gizmo().draw(ui, image);
            drawViewportToolbar(ui, input.gizmo(), image);
        }
        drawDialogs(ui);
        ImGui::Render();
        if (options.frameWait && showThisFramesEdits(ui, view, interop, editsBefore)) {
            newFrame = true;
            ++renderedFrames;
        }
        glViewport(0, 0, fbw, fbh);
        glClearColor(0.12f, 0.12f, 0.13f, 1.0f);
        glClear(GL_COLOR_BUFFER_BIT);
        view.setReference(ui.worker.errors().reference());
        ui.updateColorView();
        view.setColorView(ui.colorView);
        image = view.draw(ui.doc().viewer, ui.compare, 0.0f, top, viewWidth, viewHeight, float(fbh), scale);
        glViewport(0, 0, fbw, fbh);
        ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
        // --frames: done after that many frames with new samples, or once the frame on screen
        // has the --spp target.
        const bool sppReached = options.spp > 0 && ui.lastFrame.stats.samplesPerPixel >= options.spp;
        const bool framesDone = options.frames >= 0 && (renderedFrames >= options.frames || sppReached) &&
                                !ui.loading && view.hasImage();
        if (screenshot || (framesDone && !options.screenshotPath.empty())) {
            // F12 without --screenshot: numbered files in the working folder, never overwritten.
            const bool named = !options.screenshotPath.empty();
            std::string path =
                screenshotPath(named ? options.screenshotPath : kScreenshotName, screenshots++);
            while (!named && std::filesystem::exists(path))
                path = screenshotPath(kScreenshotName, screenshots++);
            try {
                writeWindowScreenshot(path, fbw, fbh);
                ui.notify("Screenshot: " + path);
            } catch (const std::exception& e) {
                std::fprintf(stderr, "pathtracer: %s\n", e.what());
                ui.showError(e.what());
                if (framesDone) return 1;
            }
        }
        glfwSwapBuffers(window.handle);
        if (newFrame) noteSwap(ui, latencyLog);
        inputEvents().endFrame();
        if (framesDone) break;
        activity.moving = input.moving() || ImGui::IsAnyMouseDown();
        activity.progress = ui.loading || !ui.worker.status().stage.empty() || resolution.settling();
        activity.textInput = ImGui::GetIO().WantTextInput;
        wait = redraw.afterFrame(activity);
    }
    return 0;
}

}  // namespace

int runEditor(const EditorOptions& options) {
    const std::string backendName = chooseBackend(options.backend);
    std::unique_ptr<Backend> backend = createBackend(backendName);
    EditorSession session(std::move(backend));
    std::unique_ptr<Window> window;
    try {
        window = std::make_unique<Window>(options);
    } catch (const std::exception& e) {
        std::fprintf(stderr, "pathtracer: %s\n", e.what());
        return 1;
    }
    // The CPU backend's threads on every core, niced below the window's (their file says why).
    BackgroundRenderThreads backgroundRenderThreads;
    RenderWorker worker(
        session, [] { glfwPostEmptyEvent(); }, lowerThisThreadsPriority);
    EditorUi ui(session, worker, options);
    ui.backendName = backendName;
    ui.backendCaps = session.backend().capabilities();
    ui.layout = loadPanelLayout(window->scale);
    worker.edit([&](EditorSession& s) {
        ViewerSettings viewer = s.document().viewer;
        viewer.targetSpp = options.spp;
        s.execute(setViewer(s.document(), viewer));
    });
    // Loaded on its own thread, so the window shows progress from the start.
    if (!options.scenePath.empty()) ui.loadScene(options.scenePath);
    if (!options.referencePath.empty()) {
        ui.loadReference(options.referencePath);
        if (!ui.errors.empty() && options.frames >= 0) {
            std::fprintf(stderr, "pathtracer: %s\n", ui.errors.front().c_str());
            return 1;
        }
    }
    const std::string renderer = glString(GL_RENDERER), version = glString(GL_VERSION);
    ui.glRenderer = renderer + ", OpenGL " + version;
    std::optional<LatencyLog> latencyLog;
    try {
        latencyLog.emplace(options.latencyLogPath);
    } catch (const std::runtime_error& e) {
        std::fprintf(stderr, "pathtracer: %s\n", e.what());
        return 1;
    }
    latencyLog->glContext(backendName, renderer, version);
    const int status = frameLoop(*window, ui, options, *latencyLog);
    savePanelLayout(ui.layout);
    return status;
}

}  // namespace pt::editor
