#ifndef GLTestProgress_h
#define GLTestProgress_h
/**
 * @file GLTestProgress.h
 * @brief Test helper for progress and abort of the GeoLattice filters and writers. A
 * GLTestProgress records every ProgressEvent of one algorithm and can set AbortExecute from
 * inside one, as ParaView's stop button does. Two checks build on it:
 *
 *   glExpectProgressReport(filter, 5);   // runs filter->Update()
 *     the progress values start at 0, never go back, end at 1, and hold at least 5 distinct
 *     values strictly between 0 and 1 (the filter's own reports: the executive only adds 0 and 1)
 *
 *   glExpectCleanAbort(filter, glAbortAt(0.3));  // at the first event >= 0.3 (after the executive's 0)
 *     the abort was requested and then: no error or warning, empty outputs, no progress event
 *     of the filter after the request (it stopped at its next check; the executive's closing
 *     1.0 aside), and the filter recovers: with
 *     AbortExecute off again, a new run gives non-empty outputs without errors.
 *
 * Writers pass `run` (Write()) and `isEmpty` (nothing written) instead of the defaults. The
 * filter's input should be up to date before (only the filter under test is observed).
 */
#include "GLTestErrorObserver.h"

#include <vtkAlgorithm.h>
#include <vtkCommand.h>
#include <vtkDataSet.h>
#include <vtkFieldData.h>
#include <vtkNew.h>

#include <gtest/gtest.h>

#include <chrono>
#include <functional>
#include <set>
#include <sstream>
#include <string>
#include <vector>

/// When GLTestProgress sets AbortExecute: at the first ProgressEvent with index >= AfterEvents
/// (0-based, so the default 1 skips the executive's initial 0) and value >= AtLeast.
struct GLAbortRequest {
  int AfterEvents = 1;
  double AtLeast = 0.0;
};

/// The abort request at the first progress value >= atLeast.
inline GLAbortRequest glAbortAt(double atLeast) {
  GLAbortRequest request;
  request.AtLeast = atLeast;
  return request;
}

class GLTestProgress : public vtkCommand {
public:
  static GLTestProgress* New() { return new GLTestProgress; }
  vtkTypeMacro(GLTestProgress, vtkCommand);

  /// Start recording the ProgressEvents of `algorithm` (one algorithm per recorder).
  void Observe(vtkAlgorithm* algorithm) {
    this->Algorithm = algorithm;
    this->Tag = algorithm->AddObserver(vtkCommand::ProgressEvent, this);
  }
  void StopObserving() {
    if (this->Algorithm) {
      this->Algorithm->RemoveObserver(this->Tag);
      this->Algorithm = nullptr;
    }
  }
  /// Set AbortExecute on the observed algorithm as `request` says.
  void AbortWhen(const GLAbortRequest& request) {
    this->Request = request;
    this->Armed = true;
  }

  void Execute(vtkObject* caller, unsigned long, void* callData) override {
    const double value = callData ? *static_cast<double*>(callData) : -1.0;
    this->Values.push_back(value);
    if (this->Armed && this->AbortIndex < 0 &&
        static_cast<int>(this->Values.size()) - 1 >= this->Request.AfterEvents &&
        value >= this->Request.AtLeast) {
      static_cast<vtkAlgorithm*>(caller)->AbortExecuteOn();
      this->AbortIndex = static_cast<int>(this->Values.size()) - 1;
      this->AbortTime = std::chrono::steady_clock::now();
    }
  }

  const std::vector<double>& GetValues() const { return this->Values; }
  bool AbortRequested() const { return this->AbortIndex >= 0; }
  /// The value of the event in which the abort was requested (-1 if none).
  double AbortValue() const {
    return this->AbortIndex >= 0 ? this->Values[this->AbortIndex] : -1.0;
  }
  /// Progress events of the filter after the one that requested the abort. The executive of
  /// this VTK closes every execution with UpdateProgress(1.0), aborted or not: a single last
  /// 1.0 is not counted.
  int EventsAfterAbort() const {
    if (this->AbortIndex < 0) {
      return 0;
    }
    int after = static_cast<int>(this->Values.size()) - 1 - this->AbortIndex;
    if (after > 0 && this->Values.back() == 1.0) {
      --after;
    }
    return after;
  }
  std::chrono::steady_clock::time_point GetAbortTime() const { return this->AbortTime; }
  /// The values, for failure messages.
  std::string Text() const {
    std::ostringstream s;
    for (double v : this->Values) {
      s << v << " ";
    }
    return s.str();
  }

private:
  vtkAlgorithm* Algorithm = nullptr;
  unsigned long Tag = 0;
  bool Armed = false;
  GLAbortRequest Request;
  std::vector<double> Values;
  int AbortIndex = -1;
  std::chrono::steady_clock::time_point AbortTime;
};

/// True if no output port of `algorithm` holds points, cells or field arrays (an aborted
/// filter leaves initialized outputs; e.g. the collision verifier's verdict is field data only).
inline bool glOutputsEmpty(vtkAlgorithm* algorithm) {
  for (int port = 0; port < algorithm->GetNumberOfOutputPorts(); ++port) {
    vtkDataSet* ds = vtkDataSet::SafeDownCast(algorithm->GetOutputDataObject(port));
    if (ds && (ds->GetNumberOfPoints() > 0 || ds->GetNumberOfCells() > 0 ||
               ds->GetFieldData()->GetNumberOfArrays() > 0)) {
      return false;
    }
  }
  return true;
}

/// Runs `algorithm` (default: Update()) and checks its progress report (see the file comment).
inline void glExpectProgressReport(vtkAlgorithm* algorithm, int minInteriorValues,
                                   std::function<void()> run = {}) {
  SCOPED_TRACE(std::string("progress of ") + algorithm->GetClassName());
  vtkNew<GLTestProgress> progress;
  progress->Observe(algorithm);
  vtkNew<GLTestErrorObserver> errors;
  errors->Observe(algorithm);
  algorithm->Modified();
  if (run) {
    run();
  } else {
    algorithm->Update();
  }
  progress->StopObserving();
  EXPECT_FALSE(errors->HasError()) << errors->Errors();
  const std::vector<double>& v = progress->GetValues();
  ASSERT_GE(v.size(), 2u);
  EXPECT_EQ(v.front(), 0.0) << progress->Text();
  EXPECT_EQ(v.back(), 1.0) << progress->Text();
  std::set<double> interior;
  for (size_t i = 0; i < v.size(); ++i) {
    EXPECT_TRUE(v[i] >= 0.0 && v[i] <= 1.0) << "value " << i << ": " << progress->Text();
    if (i > 0) {
      EXPECT_GE(v[i], v[i - 1]) << "progress went back at event " << i << ": " << progress->Text();
    }
    if (v[i] > 0.0 && v[i] < 1.0) {
      interior.insert(v[i]);
    }
  }
  EXPECT_GE(static_cast<int>(interior.size()), minInteriorValues) << progress->Text();
}

/// Aborts `algorithm` from a progress observer as `request` says and checks that it stops
/// cleanly, then recovers (see the file comment). isEmpty: default glOutputsEmpty.
inline void glExpectCleanAbort(vtkAlgorithm* algorithm, const GLAbortRequest& request,
                               std::function<void()> run = {}, std::function<bool()> isEmpty = {}) {
  SCOPED_TRACE(std::string("abort of ") + algorithm->GetClassName());
  if (!run) {
    run = [algorithm] {
      algorithm->Update();
    };
  }
  if (!isEmpty) {
    isEmpty = [algorithm] {
      return glOutputsEmpty(algorithm);
    };
  }
  vtkNew<GLTestErrorObserver> errors;
  errors->Observe(algorithm);
  {
    vtkNew<GLTestProgress> progress;
    progress->Observe(algorithm);
    progress->AbortWhen(request);
    algorithm->Modified();
    run();
    const auto returned = std::chrono::steady_clock::now();
    progress->StopObserving();
    ASSERT_TRUE(progress->AbortRequested())
        << "no progress event to abort at: " << progress->Text();
    EXPECT_EQ(progress->EventsAfterAbort(), 0)
        << "progress reported after the abort at " << progress->AbortValue() << ": "
        << progress->Text();
    EXPECT_LT(std::chrono::duration<double>(returned - progress->GetAbortTime()).count(), 10.0);
    EXPECT_EQ(errors->GetErrorCount(), 0) << errors->Errors();
    EXPECT_EQ(errors->GetWarningCount(), 0) << errors->Warnings();
    EXPECT_TRUE(isEmpty()) << "output left after the abort at " << progress->AbortValue();
  }
  // Recovery: the next run (the user presses Apply again) computes everything.
  errors->Clear();
  algorithm->AbortExecuteOff();
  algorithm->Modified();
  run();
  EXPECT_FALSE(errors->HasError()) << errors->Errors();
  EXPECT_FALSE(isEmpty()) << "no output after the abort and a new run";
}

#endif
