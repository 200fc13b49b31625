#ifndef vtkGLParallel_h
#define vtkGLParallel_h
/**
 * @file vtkGLParallel.h
 * @brief The GeoLattice filters in an MPI run (e.g. `mpiexec -n 2 pvbatch`, or pvserver on
 * several processes). Every GeoLattice filter is a global algorithm: the tet mesh, the heat
 * method, the layers' sub-graphs, the printing order and the toolpath all need the whole part at
 * once, so a filter runs on one process only:
 *  - one process holds all the input data (the usual case: GL Mesh Reader cannot split a file,
 *    so ParaView runs it on rank 0 only and the other ranks get empty inputs): that process
 *    computes, on its own data, nothing is sent;
 *  - several processes hold parts of it (a partitioned data set, e.g. after Redistribute
 *    DataSet or from a .pvtu): the parts are gathered on rank 0 (each input port separately,
 *    ghost cells dropped, coincident points merged exactly, the field data of the first part
 *    kept) and rank 0 computes;
 *  - no process has data: rank 0 runs the filter, which reports the empty input as in a serial
 *    run, once.
 * Every other process produces empty outputs without any message. So the results live on one
 * rank and equal the serial ones (for gathered parts up to the point and cell order), and the
 * filters downstream see the same situation again.
 *
 * This applies when the pipeline asks each process for its piece of the data (update piece
 * `rank` of `processes` pieces: ParaView's parallel updates). When every process is asked for
 * the whole data (piece 0 of 1: each process runs the whole pipeline on its own copy, e.g. a
 * writer proxy updated on every rank), a filter computes on its own input like in a serial run,
 * and of the writers only rank 0 writes (the others would write the same file).
 *
 * ParallelInputs is collective over vtkMultiProcessController::GetGlobalController() in the first
 * case: every process must construct it in the same RequestData (all GeoLattice filters do, before
 * anything else; ParaView updates a pipeline on every process). Without a controller or with
 * one process it does nothing.
 */
#include "vtkGLRequest.h"

#include <vtkSmartPointer.h>

#include <vector>

class vtkAlgorithm;
class vtkDataObject;
class vtkInformationVector;

namespace geolattice {

class ParallelInputs {
public:
  /// The first data object of input ports 0 .. ports-1 of a filter's RequestData; the piece
  /// request is that of output port 0. Collective (see the file comment).
  ParallelInputs(vtkInformationVector** inputVector, int ports, vtkInformationVector* outputVector);
  /// For a writer's WriteData: its input (port 0) and the piece request on it. Collective.
  explicit ParallelInputs(vtkAlgorithm* writer);

  /// False: another process computes; this one outputs empty data and reports nothing.
  bool Computes() const { return this->ComputesHere; }
  /// The data object of `port` to compute on (the local one, or the gathered one on rank 0).
  vtkDataObject* Get(int port) const { return this->Inputs[port]; }
  template <class T>
  T* Get(int port) const {
    return T::SafeDownCast(this->Inputs[port]);
  }
  /// Whether the inputs were gathered from several processes.
  bool Gathered() const { return this->WasGathered; }

private:
  /// local: this process's data object of each input port (null = none); pieces: the number of
  /// pieces the pipeline asks for (UPDATE_NUMBER_OF_PIECES, <= 1: the whole data).
  void Distribute(const std::vector<vtkDataObject*>& local, int pieces, bool writer);

  std::vector<vtkSmartPointer<vtkDataObject>> Inputs;
  bool ComputesHere = true;
  bool WasGathered = false;
};

/// A filter's RequestData as every GeoLattice filter runs it: the first `ports` inputs
/// (ParallelInputs, collective), the outputs cleared, nothing more on a process that does not
/// compute, and `body(inputs)` under VTK's error contract (runRequest of vtkGLRequest.h):
///   return gl::runRequest(this, inputVector, 1, outputVector,
///                         [&](const gl::ParallelInputs& inputs) { ... });
template <class Body>
int runRequest(vtkAlgorithm* algorithm, vtkInformationVector** inputVector, int ports,
               vtkInformationVector* outputVector, Body&& body) {
  const ParallelInputs inputs(inputVector, ports, outputVector);
  clearOutputs(outputVector);
  if (!inputs.Computes()) {
    return 1;  // another process has the data
  }
  return runRequest(algorithm, outputVector, [&] { body(inputs); });
}

/// True if `data` holds anything to compute on (points or cells of a vtkDataSet; for another
/// data object, a non-zero number of elements).
bool hasData(vtkDataObject* data);

}  // namespace geolattice
#endif
