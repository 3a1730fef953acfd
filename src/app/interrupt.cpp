/// @file interrupt.cpp
/// @brief The signal flag behind InterruptGuard (interrupt.hpp).
#include "app/interrupt.hpp"

#include <csignal>

namespace stepwise::cli {

namespace {

/// Written by the handler, read between steps: the one thing a handler may safely do.
volatile std::sig_atomic_t received = 0;

extern "C" void remember(int signal) { received = signal; }

struct sigaction previousInterrupt {};
struct sigaction previousTerminate {};

}  // namespace

InterruptGuard::InterruptGuard() {
    received = 0;
    struct sigaction action {};
    action.sa_handler = remember;
    sigemptyset(&action.sa_mask);
    action.sa_flags = SA_RESTART;  // a write the signal interrupts is restarted, not failed with EINTR
    sigaction(SIGINT, &action, &previousInterrupt);
    sigaction(SIGTERM, &action, &previousTerminate);
}

InterruptGuard::~InterruptGuard() {
    sigaction(SIGINT, &previousInterrupt, nullptr);
    sigaction(SIGTERM, &previousTerminate, nullptr);
}

int InterruptGuard::signalReceived() { return received; }

int exitCodeForSignal(int signal) { return 128 + signal; }

}  // namespace stepwise::cli
