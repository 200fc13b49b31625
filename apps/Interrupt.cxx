#include "Interrupt.h"

#include "GLPrintPipeline.h"

#include <vtkAlgorithm.h>
#include <vtkCommand.h>

#include <csignal>

namespace geolattice {

namespace {

volatile std::sig_atomic_t gInterrupted = 0;

extern "C" void onInterrupt(int) {
  gInterrupted = 1;
  GLPrintPipeline::RequestStop();
  std::signal(SIGINT, SIG_DFL);  // a second Ctrl-C ends the process
}

}  // namespace

InterruptHandler::InterruptHandler() {
  gInterrupted = 0;
  GLPrintPipeline::ClearStopRequest();
  this->Previous = std::signal(SIGINT, onInterrupt);
}

InterruptHandler::~InterruptHandler() {
  std::signal(SIGINT, this->Previous == SIG_ERR ? SIG_DFL : this->Previous);
}

bool InterruptHandler::Interrupted() {
  return gInterrupted != 0;
}

AbortOnInterrupt::AbortOnInterrupt(const std::vector<vtkAlgorithm*>& algorithms)
    : Algorithms(algorithms) {
  this->Command->SetCallback([](vtkObject* caller, unsigned long, void*, void*) {
    if (gInterrupted) {
      static_cast<vtkAlgorithm*>(caller)->SetAbortExecute(1);
    }
  });
  for (vtkAlgorithm* a : this->Algorithms) {
    this->Tags.push_back(a->AddObserver(vtkCommand::ProgressEvent, this->Command));
  }
}

AbortOnInterrupt::~AbortOnInterrupt() {
  for (size_t i = 0; i < this->Algorithms.size(); ++i) {
    this->Algorithms[i]->RemoveObserver(this->Tags[i]);
  }
}

}  // namespace geolattice
