#pragma once
// Ctrl-C during a long render: while an InterruptCatcher lives, the first SIGINT only raises a
// flag that the render loop polls between batches, so the samples taken so far are written
// instead of thrown away; a second SIGINT ends the process as usual.
namespace pt::cli {

class InterruptCatcher {
public:
    InterruptCatcher();   // installs the handler (one catcher at a time)
    ~InterruptCatcher();  // restores the previous one
    InterruptCatcher(const InterruptCatcher&) = delete;
    InterruptCatcher& operator=(const InterruptCatcher&) = delete;

    bool interrupted() const;
};

// The exit status of a process ended by SIGINT, by shell convention (128 + 2).
constexpr int kInterruptedExitCode = 130;

}  // namespace pt::cli
