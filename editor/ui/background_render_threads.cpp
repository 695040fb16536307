#include "editor/ui/background_render_threads.h"

#include <sys/resource.h>
#include <sys/syscall.h>
#include <unistd.h>

namespace pt::editor {

void lowerThisThreadsPriority() {
    // setpriority on a thread id sets that thread's nice value on Linux (not POSIX's meaning).
    const auto tid = id_t(syscall(SYS_gettid));
    (void)setpriority(PRIO_PROCESS, tid, BackgroundRenderThreads::kNice);  // best effort
}

void BackgroundRenderThreads::on_scheduler_entry(bool isWorker) {
    if (isWorker) lowerThisThreadsPriority();
}

}  // namespace pt::editor
