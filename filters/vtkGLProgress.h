#ifndef vtkGLProgress_h
#define vtkGLProgress_h
/**
 * @file vtkGLProgress.h
 * @brief Progress and abort for the GeoLattice filters: the callbacks of the core options
 * structs (core/common/Progress.h) mapped onto vtkAlgorithm::UpdateProgress and AbortExecute.
 * An aborted filter returns 1 with empty outputs and reports nothing (the core throws
 * "... aborted", which the filters' catch blocks keep quiet when GetAbortExecute() is set).
 */
#include <vtkAlgorithm.h>

#include <functional>

namespace geolattice {

/// Core progress callback: fraction f of a core call -> UpdateProgress(lo + (hi - lo) f).
inline std::function<void(double)> progressRange(vtkAlgorithm* algorithm, double lo, double hi) {
  return [algorithm, lo, hi](double f) {
    algorithm->UpdateProgress(lo + (hi - lo) * f);
  };
}

/// Core abort callback: the algorithm's AbortExecute flag (set by ParaView's stop button or a
/// ProgressEvent observer).
inline std::function<bool()> abortFlag(vtkAlgorithm* algorithm) {
  return [algorithm] {
    return algorithm->GetAbortExecute() != 0;
  };
}

/// UpdateProgress(f) (observers may set AbortExecute there), then whether to abort.
inline bool progressAborts(vtkAlgorithm* algorithm, double f) {
  algorithm->UpdateProgress(f);
  return algorithm->GetAbortExecute() != 0;
}

}  // namespace geolattice
#endif
