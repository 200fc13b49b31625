#pragma once
/// @file CrashReport.h
/// @brief When the CLI crashes (SIGSEGV, SIGBUS, SIGFPE, SIGILL, SIGABRT), one line on stderr
/// names the signal and the stage that was running, followed by the call stack (glibc's
/// backtrace, symbol names where the libraries export them); then the signal takes its default
/// action, so the exit status still says what happened (e.g. -11) and a core dump is still made
/// where enabled. Why: a crash seen once, on another machine (a CI run, a user's part), is
/// otherwise only an exit status.
///
/// Only what is async-signal-safe runs in the handler (write, backtrace_symbols_fd; backtrace is
/// called once at installation so that its library is loaded before any crash). A stack overflow
/// of the main thread is reported from an alternate signal stack; child processes forked by the
/// CLI (TetGen's) crash silently, as before: their parent reports their signal.
namespace geolattice {

/// Installs the handlers for the rest of the process's life.
void installCrashReport();

/// The stage the crash report names from now on (a string that lives as long as the process,
/// e.g. a literal; nullptr: none).
void setCrashStage(const char* stage);

}  // namespace geolattice
