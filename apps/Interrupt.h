#pragma once
/// @file Interrupt.h
/// @brief Ctrl-C in the CLI stops the running stage the way ParaView's stop button does: the
/// SIGINT handler only sets flags (GLPrintPipeline::RequestStop, which every filter's abort poll
/// sees, and ours, which an observer turns into SetAbortExecute(1) at the next progress event);
/// the filter returns with empty outputs, and the run ends with report.json naming the interrupted stage (exit status 130). A second Ctrl-C
/// kills the process at once (the default action is restored by the first).
#include <vtkCallbackCommand.h>
#include <vtkNew.h>

#include <vector>

class vtkAlgorithm;

namespace geolattice {

/// Installs the SIGINT handler while alive (restores the previous one after).
class InterruptHandler {
public:
  InterruptHandler();
  ~InterruptHandler();
  InterruptHandler(const InterruptHandler&) = delete;
  InterruptHandler& operator=(const InterruptHandler&) = delete;
  /// Ctrl-C was pressed since the handler was installed.
  static bool Interrupted();

private:
  void (*Previous)(int) = nullptr;
};

/// While alive, aborts any of `algorithms` at its next progress event after a Ctrl-C.
class AbortOnInterrupt {
public:
  explicit AbortOnInterrupt(const std::vector<vtkAlgorithm*>& algorithms);
  ~AbortOnInterrupt();
  AbortOnInterrupt(const AbortOnInterrupt&) = delete;
  AbortOnInterrupt& operator=(const AbortOnInterrupt&) = delete;

private:
  std::vector<vtkAlgorithm*> Algorithms;
  std::vector<unsigned long> Tags;
  vtkNew<vtkCallbackCommand> Command;
};

}  // namespace geolattice
