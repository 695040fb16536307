#include "cli/interrupt.h"

#include <csignal>

namespace pt::cli {

namespace {

volatile std::sig_atomic_t gInterrupted = 0;
struct sigaction gPrevious;

void onInterrupt(int) { gInterrupted = 1; }

}  // namespace

InterruptCatcher::InterruptCatcher() {
    gInterrupted = 0;
    struct sigaction action {};
    action.sa_handler = onInterrupt;
    sigemptyset(&action.sa_mask);
    action.sa_flags = SA_RESETHAND;  // the second Ctrl-C gets the default: the process ends
    sigaction(SIGINT, &action, &gPrevious);
}

InterruptCatcher::~InterruptCatcher() { sigaction(SIGINT, &gPrevious, nullptr); }

bool InterruptCatcher::interrupted() const { return gInterrupted != 0; }

}  // namespace pt::cli
