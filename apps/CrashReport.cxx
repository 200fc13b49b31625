#include "CrashReport.h"

#include <atomic>
#include <csignal>
#include <cstring>

#include <execinfo.h>
#include <unistd.h>

namespace geolattice {

namespace {

std::atomic<const char*> gStage{nullptr};
pid_t gPid = 0;  // the process that installed the handlers (not a forked child)
constexpr int kSignals[] = {SIGSEGV, SIGBUS, SIGFPE, SIGILL, SIGABRT};

void say(const char* text) {
  if (text) {
    const ssize_t ignored = ::write(STDERR_FILENO, text, std::strlen(text));
    (void)ignored;
  }
}

const char* signalName(int sig) {
  switch (sig) {
    case SIGSEGV:
      return "SIGSEGV (invalid memory access)";
    case SIGBUS:
      return "SIGBUS (bus error)";
    case SIGFPE:
      return "SIGFPE (arithmetic error)";
    case SIGILL:
      return "SIGILL (illegal instruction)";
    case SIGABRT:
      return "SIGABRT (aborted)";
    default:
      return "a signal";
  }
}

extern "C" void onCrash(int sig) {
  // SA_RESETHAND: the default action is back; the signal is blocked until this returns.
  if (::getpid() == gPid) {
    say("geolattice: crashed with ");
    say(signalName(sig));
    const char* stage = gStage.load();
    if (stage) {
      say(" in stage ");
      say(stage);
    }
    say("; call stack:\n");
    void* frames[64];
    const int n = ::backtrace(frames, 64);
    ::backtrace_symbols_fd(frames, n, STDERR_FILENO);
  }
  // Pending until this returns, then taken with the default action: the process ends by it
  // whether it was a fault or sent (kill, abort).
  ::raise(sig);
}

}  // namespace

void installCrashReport() {
  gPid = ::getpid();
  void* frame[1];
  ::backtrace(frame, 1);  // loads libgcc now, not in the handler
  // The main thread's handler runs on a stack of its own, so that its stack overflowing is
  // reported too.
  static char alternateStack[64 * 1024];
  stack_t ss{};
  ss.ss_sp = alternateStack;
  ss.ss_size = sizeof alternateStack;
  ::sigaltstack(&ss, nullptr);
  struct sigaction action {};
  action.sa_handler = onCrash;
  action.sa_flags = SA_RESETHAND | SA_ONSTACK;
  sigemptyset(&action.sa_mask);
  for (int sig : kSignals) {
    ::sigaction(sig, &action, nullptr);
  }
}

void setCrashStage(const char* stage) {
  gStage.store(stage);
}

}  // namespace geolattice
