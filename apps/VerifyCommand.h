#pragma once
/// @file VerifyCommand.h
/// @brief `geolattice verify OUTDIR`: re-checks what `geolattice run` saved with the independent
/// collision verifier (vtkGLCollisionVerifier): the newer (by modification time) of toolpath.vtp
/// (time = PointIndex, air points are stations but not material) and lattice.vtp (time =
/// PrintOrder per sub-graph), and says which one it checked.
namespace geolattice {

/// argv[1] == "verify". Returns the exit status: 0 collision-free, 3 collision, 1 error (throws
/// GeoLatticeError), 2 usage (throws UsageError).
int runVerifyCommand(int argc, char** argv);

}  // namespace geolattice
