#pragma once
/// @file VerifyCommand.h
/// @brief `geolattice verify OUTDIR`: re-checks the printing order saved by `geolattice run`
/// with the independent collision verifier (vtkGLCollisionVerifier).
namespace geolattice {

/// argv[1] == "verify". Returns the exit status: 0 collision-free, 3 collision, 1 error (throws
/// GeoLatticeError), 2 usage (throws UsageError).
int runVerifyCommand(int argc, char** argv);

} // namespace geolattice
