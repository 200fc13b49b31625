#ifndef vtkGLProgress_h
#define vtkGLProgress_h
/**
 * @file vtkGLProgress.h
 * @brief Progress and abort for the GeoLattice filters: the callbacks of the core options
 * structs (core/common/Progress.h) mapped onto vtkAlgorithm::UpdateProgress and AbortExecute.
 * An aborted filter returns 1 with empty outputs and reports nothing (the core throws
 * "... aborted", which the filters' catch blocks keep quiet when GetAbortExecute() is set).
 */
#include "GeoLatticeFiltersModule.h"

#include <vtkAlgorithm.h>

#include <atomic>
#include <functional>

namespace geolattice {

/// Core progress callback: fraction f of a core call -> UpdateProgress(lo + (hi - lo) f).
inline std::function<void(double)> progressRange(vtkAlgorithm* algorithm, double lo, double hi) {
  return [algorithm, lo, hi](double f) {
    algorithm->UpdateProgress(lo + (hi - lo) * f);
  };
}

/// A process-wide stop request, e.g. from the CLI's SIGINT handler (a lock-free atomic, so a
/// signal handler may set it): every core abort callback sees it at its next poll, also where
/// no progress event fires in between (TetGen, the axis clearance).
GEOLATTICEFILTERS_EXPORT std::atomic<bool>& stopRequest();

/// Core abort callback: the algorithm's AbortExecute flag (set by ParaView's stop button or a
/// ProgressEvent observer) or the process-wide stopRequest().
inline std::function<bool()> abortFlag(vtkAlgorithm* algorithm) {
  return [algorithm] {
    if (stopRequest().load(std::memory_order_relaxed)) {
      algorithm->SetAbortExecute(1);  // so the filter treats the core's "aborted" as a stop
    }
    return algorithm->GetAbortExecute() != 0;
  };
}

/// UpdateProgress(f) (observers may set AbortExecute there), then whether to abort.
inline bool progressAborts(vtkAlgorithm* algorithm, double f) {
  algorithm->UpdateProgress(f);
  return abortFlag(algorithm)();
}

}  // namespace geolattice
#endif
