#include "editor/render_worker.h"

#include <algorithm>
#include <chrono>
#include <thread>

#include "assets/message_text.h"
#include "editor/step_passes.h"

namespace pt::editor {

RenderWorker::RenderWorker(EditorSession& session, std::function<void()> onUpdate,
                           const std::function<void()>& onStart)
    : session_(session), onUpdate_(std::move(onUpdate)), thread_([this, onStart] {
          if (onStart) onStart();
          run();
      }) {}

RenderWorker::~RenderWorker() {
    stop_ = true;
    session_.interruptRender();  // a pass in flight would hold the window open until it ends
    wake();
    thread_.join();
}

void RenderWorker::wake() {
    {
        std::lock_guard<std::mutex> lock(wakeMutex_);
        woken_ = true;
    }
    wake_.notify_all();
}

void RenderWorker::edit(const std::function<void(EditorSession&)>& change) {
    {
        std::unique_lock<std::shared_mutex> lock(sceneMutex_);
        change(session_);
    }
    wake();
}

bool RenderWorker::tryEdit(const std::function<void(EditorSession&)>& change) {
    {
        std::unique_lock<std::shared_mutex> lock(sceneMutex_, std::try_to_lock);
        if (!lock.owns_lock()) return false;
        change(session_);
    }
    wake();
    return true;
}

void RenderWorker::withBackend(const std::function<void(EditorSession&)>& use) {
    ++backendWaiters_;
    std::unique_lock<std::mutex> lock(backendMutex_);
    --backendWaiters_;
    use(session_);
}

bool RenderWorker::takeFrame(DisplayFrame& out) {
    std::lock_guard<std::mutex> lock(frameMutex_);
    if (frame_.serial == taken_) return false;
    out = frame_;
    taken_ = frame_.serial;
    return true;
}

// Called with the backend lock held, as the frame is published; `wanted` while the window takes
// the beauty through interop (else the last copy is withdrawn).
void RenderWorker::copyFrameToDevice(bool wanted, bool denoise) {
    const Backend& backend = session_.backend();
    std::lock_guard<std::mutex> lock(deviceFrameMutex_);
    deviceFrameValid_ = false;
    if (!wanted || !backend.capabilities().deviceFrames) return;
    if (!deviceFrame_ || deviceFrameWidth_ != backend.width() || deviceFrameHeight_ != backend.height()) {
        deviceFrame_.reset();
        deviceFrame_ = backend.allocateDeviceFrame();
        deviceFrameWidth_ = backend.width();
        deviceFrameHeight_ = backend.height();
    }
    deviceFrameValid_ = deviceFrame_ && session_.copyDisplayedToDevice(denoise, deviceFrame_.get());
}

bool RenderWorker::withDeviceFrame(
    const std::function<void(const void* rgba, uint32_t width, uint32_t height)>& use) {
    std::lock_guard<std::mutex> lock(deviceFrameMutex_);
    if (!deviceFrameValid_) return false;
    use(deviceFrame_.get(), deviceFrameWidth_, deviceFrameHeight_);
    return true;
}

bool RenderWorker::waitForFrame(uint64_t edit, double seconds) {
    std::unique_lock<std::mutex> lock(frameMutex_);
    return framePublished_.wait_for(lock, std::chrono::duration<double>(seconds), [&] {
        return frame_.serial != taken_ && frame_.edit >= edit && frame_.stats.samplesPerPixel > 0;
    });
}

WorkerStatus RenderWorker::status() const {
    std::lock_guard<std::mutex> lock(statusMutex_);
    return status_;
}

void RenderWorker::setStage(const std::string& stage, double fraction) {
    {
        std::lock_guard<std::mutex> lock(statusMutex_);
        status_.stage = stage;
        status_.fraction = fraction;
    }
    if (onUpdate_) onUpdate_();
}

void RenderWorker::publishFrame(int32_t aov, bool denoise) {
    DisplayFrame next;
    const Backend& backend = session_.backend();
    next.width = backend.width();
    next.height = backend.height();
    next.aov = aov;
    next.document = session_.syncedDocument();
    next.edit = session_.syncedEdit();
    next.stats = backend.stats();
    if (hostFrames_ || aov >= 0) session_.readDisplayed(aov, denoise, next.rgba);
    copyFrameToDevice(!hostFrames_ && aov < 0, denoise);
    {
        std::lock_guard<std::mutex> lock(frameMutex_);
        next.serial = frame_.serial + 1;
        frame_ = std::move(next);
        publishedAov_ = aov;
        publishedDenoise_ = denoise;
    }
    framePublished_.notify_all();
    if (onUpdate_) onUpdate_();
}

// Called with the backend lock held, after passes.
void RenderWorker::measureError() {
    const Backend& backend = session_.backend();
    const BackendStats stats = backend.stats();
    if (!errors_.due(stats.renderSeconds, stats.samplesPerPixel, backend.width(), backend.height())) return;
    std::vector<float> beauty;
    backend.readBeauty(beauty);
    errors_.add(stats.renderSeconds, stats.samplesPerPixel, beauty);
}

bool RenderWorker::step() {
    SceneChangeMask pending;
    uint32_t passes, target;
    int32_t aov;
    bool denoise;
    {
        std::shared_lock<std::shared_mutex> lock(sceneMutex_);
        pending = session_.pendingChanges().mask;
        const ViewerSettings& viewer = session_.document().viewer;
        passes = viewer.samplesPerFrame;  // 0: automatic, decided once the sync has run
        target = viewer.targetSpp;
        aov = viewer.aov;
        denoise = viewer.denoise;
    }
    std::lock_guard<std::mutex> backendLock(backendMutex_);
    bool changed = false;
    if (pending != SceneChanges::None && !syncRefused_) {
        std::shared_lock<std::shared_mutex> lock(sceneMutex_);
        try {
            const SyncReport report =
                session_.sync([this](const std::string& stage, double f) { setStage(stage, f); });
            // Display-only edits (exposure, tone mapper) need no new frame: the shader applies them.
            changed = report.action != "nothing";
            if (changed) errors_.restart();
            std::vector<ToggleState> toggles = session_.backend().toggleStates();
            std::lock_guard<std::mutex> status(statusMutex_);
            status_.error.clear();
            status_.toggles = std::move(toggles);
            status_.deviceMemoryBytes = session_.backend().deviceMemoryBytes();
            status_.aovs = session_.backend().aovs();
        } catch (const std::exception& e) {
            syncRefused_ = true;
            changed = true;
            std::lock_guard<std::mutex> status(statusMutex_);
            status_.error = oneLineMessage(e.what());
        }
        setStage("", 0.0);
    }
    if (syncRefused_) return false;
    if (passes == 0) passes = autoPassesPerStep(secondsPerPass_, session_.backend().stats().samplesPerPixel);
    const auto start = Clock::now();
    const uint32_t rendered = session_.render(passes, target);
    if (rendered > 0 || changed || aov != publishedAov_ || denoise != publishedDenoise_)
        publishFrame(aov, denoise);
    if (rendered > 0) measureError();  // after publishing, so the frame is not delayed by it
    const double seconds = secondsSince(start);
    if (rendered > 0) secondsPerPass_ = seconds / rendered;
    std::vector<uint32_t> alive =
        rendered > 0 ? session_.backend().pathsAlivePerBounce() : std::vector<uint32_t>{};
    std::lock_guard<std::mutex> status(statusMutex_);
    status_.denoiseSeconds = session_.lastDenoiseSeconds();
    if (rendered > 0) {
        status_.secondsPerPass = secondsPerPass_;
        status_.pathsAlivePerBounce = std::move(alive);
    }
    status_.converged = session_.converged(target);
    return rendered > 0 || changed;
}

void RenderWorker::run() {
    while (!stop_) {
        // The UI thread's turn first (a std::mutex is not fair: this thread would otherwise
        // take it back at once). It holds the backend briefly: a frame copy, a pick.
        while (backendWaiters_ > 0 && !stop_) std::this_thread::yield();
        if (step()) continue;
        // Nothing to do (converged, or a refused sync): sleep until an edit wakes us.
        std::unique_lock<std::mutex> lock(wakeMutex_);
        wake_.wait_for(lock, std::chrono::milliseconds(100), [this] { return woken_; });
        if (woken_) syncRefused_ = false;
        woken_ = false;
    }
}

}  // namespace pt::editor
