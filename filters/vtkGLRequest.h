#ifndef vtkGLRequest_h
#define vtkGLRequest_h
/**
 * @file vtkGLRequest.h
 * @brief VTK's error contract for every GeoLattice filter, in one place.
 *
 * A filter's RequestData is `return geolattice::runRequest(this, outputVector, [&] { ... });`:
 *  - the body returns normally: the request succeeded, 1;
 *  - the user pressed stop (AbortExecute; the body calls checkAbort() between its steps and the
 *    core callbacks throw "... aborted"): every output is emptied and the request returns 1
 *    without a message, as VTK's own filters do;
 *  - anything else throws: every output is emptied, the message goes to vtkErrorMacro (ParaView's
 *    Output Messages, the CLI's one-line error) and the request returns 0, so `Update()` reports
 *    the failure and the filters downstream do not run on an empty output.
 * Writers use runWrite(): the same, with the writer's error code set on failure.
 *
 * Parameters are checked first: a filter's RequestInformation is
 * `return geolattice::checkParameters(this, [&] { optionsOf(this).validate(); });`. VTK runs the
 * information pass of the whole pipeline (upstream first) before any data request, so a bad
 * parameter of any filter is reported in milliseconds, before the first expensive stage, in
 * ParaView (on Apply) and in the CLI (which calls UpdateInformation() on its last filter first).
 */
#include "common/AtomicFile.h"
#include "vtkGLProgress.h"

#include <vtkAlgorithm.h>
#include <vtkDataObject.h>
#include <vtkErrorCode.h>
#include <vtkInformation.h>
#include <vtkInformationVector.h>
#include <vtkSetGet.h>
#include <vtkWriter.h>

#include <exception>
#include <functional>

namespace geolattice {

/// Thrown by checkAbort(): the user asked to stop (not an error).
struct RequestAborted {};

/// UpdateProgress(fraction) (observers may set AbortExecute there), then throws RequestAborted if
/// the user asked to stop.
inline void checkAbort(vtkAlgorithm* algorithm, double fraction) {
  algorithm->UpdateProgress(fraction);
  if (abortFlag(algorithm)()) {
    throw RequestAborted{};
  }
}

/// Empties every output data object of a request.
inline void clearOutputs(vtkInformationVector* outputs) {
  for (int i = 0; outputs && i < outputs->GetNumberOfInformationObjects(); ++i) {
    if (vtkDataObject* data = vtkDataObject::GetData(outputs, i)) {
      data->Initialize();
    }
  }
}

/// Runs `check` as a filter's parameter check (see the file comment): a throw goes to
/// vtkErrorMacro and the request returns 0, so no data request of the pipeline runs.
template <class Check>
int checkParameters(vtkAlgorithm* algorithm, Check&& check) {
  try {
    check();
    return 1;
  } catch (const std::exception& e) {
    vtkErrorWithObjectMacro(algorithm, << e.what());
    return 0;
  }
}

/// Runs `body` as a filter's data request with VTK's error contract (see the file comment).
template <class Body>
int runRequest(vtkAlgorithm* algorithm, vtkInformationVector* outputs, Body&& body) {
  try {
    body();
    return 1;
  } catch (const RequestAborted&) {
    clearOutputs(outputs);
    return 1;
  } catch (const std::exception& e) {
    clearOutputs(outputs);
    if (algorithm->GetAbortExecute()) {
      return 1;  // the core's "... aborted": the user's stop, not an error
    }
    vtkErrorWithObjectMacro(algorithm, << e.what());
    return 0;
  }
}

/// The same for a writer's WriteData, as `this->SetErrorCode(runWrite(this, body))`: returns the
/// vtkErrorCode to set (NoError on success and on an abort, which writes nothing, silently; on a
/// failure the message goes to vtkErrorMacro, and Write() then returns 0).
/// onFailure (optional) runs after a failure, onAbort (optional) after an abort: e.g. to clear the
/// writer's result members.
template <class Body>
unsigned long runWrite(vtkWriter* writer, Body&& body, const std::function<void()>& onFailure = {},
                       const std::function<void()>& onAbort = {}) {
  auto aborted = [&] {
    if (onAbort) {
      onAbort();
    }
  };
  try {
    body();
    return vtkErrorCode::NoError;
  } catch (const RequestAborted&) {
    aborted();
    return vtkErrorCode::NoError;
  } catch (const FileWriteError& e) {
    vtkErrorWithObjectMacro(writer, << e.what());
    if (onFailure) {
      onFailure();
    }
    return vtkErrorCode::CannotOpenFileError;
  } catch (const std::exception& e) {
    if (writer->GetAbortExecute()) {
      aborted();
      return vtkErrorCode::NoError;
    }
    vtkErrorWithObjectMacro(writer, << e.what());
    if (onFailure) {
      onFailure();
    }
    return vtkErrorCode::UserError;
  }
}

}  // namespace geolattice
#endif
