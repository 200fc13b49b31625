#pragma once
/// @file TetGenRunner.h
/// @brief Runs TetGen 1.5 on a triangle surface in a child process, so that TetGen's failures
/// become GeoLatticeErrors instead of crashing the caller (e.g. ParaView).
///
/// Why a child process: in Debian's TetGen 1.5.0 every error exit (terminatetetgen: self-
/// intersections, tiny features, internal errors) frees the mesh and then throws; unwinding
/// through tetrahedralize() destroys its local tetgenmesh, which frees the same memory again
/// (double free -> SIGSEGV/SIGABRT). The child runs TetGen on a thread whose stack has no
/// exception handler, so a thrown error code reaches std::terminate without unwinding; the
/// terminate handler sends the code to the parent and exits. The child also silences TetGen's
/// stdout, and the parent can kill it when the caller aborts.
///
/// Data flow: surface -> fork -> child: TetGen with the meshing switches -> pipe (points, tets,
/// region attributes) -> parent; beside it (unless skipped) a second child runs TetGen "pdQ"
/// (self-intersection test) and sends only its verdict.
#include "common/Error.h"
#include "mesh/TetMesh.h"

#include <functional>
#include <string>
#include <vector>

namespace geolattice {

/// Thrown when a TetGen child used more than its time limit: the limit is the child's own CPU
/// time, not wall time, so that whether a run finishes does not depend on what else the machine
/// does (a compile on the other core once pushed a run past a wall-clock limit it meets alone,
/// and the part was meshed from another surface).
class TetGenTimeLimitExceeded : public GeoLatticeError {
public:
  using GeoLatticeError::GeoLatticeError;
};

/// CPU time (user + system, s) a running process of this user has used so far, from
/// /proc/PID/stat; a negative value when it cannot be read (no /proc, the process has ended).
double processCpuSeconds(int pid);

/// @brief TetGen output: points (mm), tets (TetGen's vertex order) and, with switch "A", one
/// region number per tet (regions are the parts of space separated by the input facets).
struct TetGenOutput {
  TetMesh mesh;
  std::vector<int> regions;  ///< empty without "A"
};

/// Whether runTetGen tests the surface for intersecting facets (TetGen's "d" switch) first.
enum class IntersectionTest {
  Run,   ///< in a second child process beside the meshing one; its verdict comes first
  Skip,  ///< the surface passed the test before (e.g. another edge length on the same surface)
};

/// @brief One TetGen meshing run in a child process, started on construction and read by
/// finish(): runTetGen in two halves, so that a caller can mesh a second edge length on the
/// other core meanwhile. Destroying it unread kills the child. `switches` as for runTetGen.
class TetGenRun {
public:
  TetGenRun(const TriangleSurface& surface, const std::string& switches);
  ~TetGenRun();
  TetGenRun(const TetGenRun&) = delete;
  TetGenRun& operator=(const TetGenRun&) = delete;
  /// Waits for the child and returns its mesh (at most once); errors as for runTetGen.
  TetGenOutput finish(const std::function<bool()>& shouldAbort = {}, double cpuSecondsLimit = 0);

private:
  int pid_ = -1, fd_ = -1, stderrFd_ = -1;  // the child; pid -1 once finished
  double startedAt_ = 0;                    // steady clock (s), for a wall-time fallback
};

/// @brief Mesh the PLC given by `surface` (one facet per triangle) with TetGen `switches`
/// (e.g. "pq1.414a0.4AQ"; must contain "p"), the surface tested for intersecting facets unless
/// `test` is Skip.
/// @param shouldAbort polled about every 50 ms while TetGen runs; returning true kills it.
/// @param cpuSecondsLimit the CPU time each child may use (s; 0 = no limit): a child past it is
/// killed and TetGenTimeLimitExceeded thrown. Checked with shouldAbort; where /proc cannot be
/// read, the child's wall time stands in.
/// @throws GeoLatticeError "self-intersecting surface: ..." when facets intersect, a message
/// per TetGen error code (1 memory, 2 internal, 3 intersections, 4 tiny feature, 5 close
/// facets, 10 input), "tetrahedralization aborted" on abort, or when the child process cannot
/// be started or dies (signal named); TetGenTimeLimitExceeded past the limit.
TetGenOutput runTetGen(const TriangleSurface& surface, const std::string& switches,
                       const std::function<bool()>& shouldAbort = {},
                       IntersectionTest test = IntersectionTest::Run, double cpuSecondsLimit = 0);

/// @brief TetGen's self-intersection test ("pdQ") of `surface` in a child process, waited for.
/// @throws GeoLatticeError "self-intersecting surface: TetGen found N intersecting facets", or
/// as runTetGen when the child fails, `shouldAbort` returns true or the limit is passed.
void testForIntersectingFacets(const TriangleSurface& surface,
                               const std::function<bool()>& shouldAbort = {},
                               double cpuSecondsLimit = 0);

/// Message for a TetGen terminatetetgen() error code.
std::string tetgenErrorMessage(int code);

}  // namespace geolattice
