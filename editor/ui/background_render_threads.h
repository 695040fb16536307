#pragma once
// The CPU backend's threads on every core, below the window's priority. The window used to keep
// a core to itself (TBB at cores - 1 threads), which on 2 cores left half the machine idle once
// the window stopped drawing without pause (redraw_policy.h); on all cores at equal priority,
// the window's frames slowed (F12 to screenshot at 512x512 on 2 cores: 95 -> 160 ms). Niced,
// the render threads take what the window leaves. Linux: nice is per thread there.
#include <tbb/task_scheduler_observer.h>

namespace pt::editor {

class BackgroundRenderThreads : public tbb::task_scheduler_observer {
public:
    static constexpr int kNice = 10;
    BackgroundRenderThreads() { observe(true); }
    ~BackgroundRenderThreads() override { observe(false); }
    void on_scheduler_entry(bool isWorker) override;  // lowers each thread that joins
};

// Lowers the calling thread (the editor's render thread, which takes part in its own loops).
void lowerThisThreadsPriority();

}  // namespace pt::editor
