#pragma once
// RenderWorker: the editor's render thread. It syncs the backend after edits and adds samples
// while the UI thread keeps drawing at its own rate (DESIGN.md: accumulation never blocks the
// UI). Ownership rules, which keep the two threads apart:
//   - the UI thread is the only writer of the document: it edits through edit()/tryEdit(),
//     which hold the scene lock exclusively; it reads the document without locking;
//   - the render thread reads the document only under the shared scene lock (sync) and
//     touches the backend only under the backend lock, which the UI takes for picking,
//     exporting and switching backends (withBackend());
//   - frames cross over as copies (takeFrame()).
#include <atomic>
#include <condition_variable>
#include <functional>
#include <mutex>
#include <shared_mutex>
#include <string>
#include <thread>
#include <vector>

#include "editor/editor_session.h"
#include "editor/error_tracker.h"

namespace pt::editor {

// What the viewport shows: the beauty or the selected AOV, linear RGBA float.
struct DisplayFrame {
    uint32_t width = 0, height = 0;
    std::vector<float> rgba;
    int32_t aov = -1;       // -1: the beauty
    uint64_t serial = 0;    // grows with every published frame
    uint64_t document = 0;  // the EditorSession::documentSerial() it shows
    uint64_t edit = 0;      // the EditorSession::syncedEdit() its samples include
    BackendStats stats;
};

struct WorkerStatus {
    std::string stage;      // "" when idle, else the long operation under way ("BLAS build", ...)
    double fraction = 0.0;  // of that stage
    std::string error;      // the last sync's refusal, until the next edit
    double secondsPerPass = 0.0;
    double denoiseSeconds = 0.0;  // the last denoise of a shown or exported frame (0: none yet)
    bool converged = false;
    std::vector<ToggleState> toggles;  // as the backend applies them, after the last sync
    uint64_t deviceMemoryBytes = 0;
    AovMask aovs = 0;                           // accumulated (Backend::aovs()) after the last sync
    std::vector<uint32_t> pathsAlivePerBounce;  // wavefront only, of the last wave
};

class RenderWorker {
public:
    // `onUpdate` (any thread; may be empty) is called from the render thread whenever a frame
    // is published or the status' stage changes: the window wakes to show it (glfwPostEmptyEvent)
    // instead of drawing without pause to find out.
    // `onStart` (may be empty) runs first on the render thread (the window lowers its priority).
    explicit RenderWorker(EditorSession& session, std::function<void()> onUpdate = {},
                          const std::function<void()>& onStart = {});
    ~RenderWorker();
    RenderWorker(const RenderWorker&) = delete;
    RenderWorker& operator=(const RenderWorker&) = delete;

    // UI thread: changes the document. edit() waits for a sync under way to finish; tryEdit()
    // returns false instead, so a long BVH build never freezes the window.
    void edit(const std::function<void(EditorSession&)>& change);
    bool tryEdit(const std::function<void(EditorSession&)>& change);
    // UI thread: uses the backend while the render thread is between passes. The render thread
    // lets a waiting caller in before its next batch, so a frame published for CUDA-GL interop
    // is copied within a batch of its samples, not after however many batches the lock's
    // unfairness would allow.
    void withBackend(const std::function<void(EditorSession&)>& use);

    // A frame newer than the one last taken, if any.
    bool takeFrame(DisplayFrame& out);
    // UI thread, while frames reach GL through interop (setHostFrames(false)): runs `use` with
    // the device copy the render thread made of the last published beauty (RGBA float), while
    // it is not being written; false where there is none (a host backend, an AOV on screen,
    // no frame published since). The copy is made as the frame is published, so the window
    // never waits for the batch of passes that follows it (which the backend lock would).
    bool withDeviceFrame(const std::function<void(const void* rgba, uint32_t width, uint32_t height)>& use);
    // Waits at most `seconds` for a frame, not taken yet, whose samples include `edit` (an
    // EditorSession::editSerial()); true once there is one to take. The window waits a few
    // milliseconds for an edit made in the frame it is drawing, so that the swap shows it.
    bool waitForFrame(uint64_t edit, double seconds);
    // Whether frames of the beauty carry their pixels (false while the window takes them from
    // the GPU directly through CUDA-GL interop; AOV frames always do).
    void setHostFrames(bool on) { hostFrames_ = on; }
    WorkerStatus status() const;
    // The reference image and the live error curve against it (the UI sets the reference,
    // the render thread measures after its passes).
    ErrorTracker& errors() { return errors_; }

private:
    void run();
    void wake();  // the render thread: there is new work (an edit, or stop)
    bool step();  // one sync and/or batch of passes; false when there was nothing to do
    void publishFrame(int32_t aov, bool denoise);
    void measureError();
    void setStage(const std::string& stage, double fraction);

    EditorSession& session_;
    const std::function<void()> onUpdate_;
    std::shared_mutex sceneMutex_;
    std::mutex backendMutex_;
    std::atomic<uint32_t> backendWaiters_{0};  // withBackend() callers waiting for backendMutex_
    std::mutex wakeMutex_;
    std::condition_variable wake_;
    bool woken_ = false;
    std::atomic<bool> stop_{false};
    std::atomic<bool> hostFrames_{true};
    bool syncRefused_ = false;     // render thread only: wait for the next edit before retrying
    double secondsPerPass_ = 0.0;  // render thread only: of the last step, for automatic passes

    // The render thread's device copy of the last published beauty (withDeviceFrame).
    std::mutex deviceFrameMutex_;
    std::shared_ptr<void> deviceFrame_;
    uint32_t deviceFrameWidth_ = 0, deviceFrameHeight_ = 0;
    bool deviceFrameValid_ = false;
    void copyFrameToDevice(bool wanted, bool denoise);

    mutable std::mutex frameMutex_;
    std::condition_variable framePublished_;
    DisplayFrame frame_;
    uint64_t taken_ = 0;
    int32_t publishedAov_ = -2;
    bool publishedDenoise_ = false;

    ErrorTracker errors_;

    mutable std::mutex statusMutex_;
    WorkerStatus status_;
    std::thread thread_;
};

}  // namespace pt::editor
