#pragma once
/// @file RunCommand.h
/// @brief `geolattice run`: the stages of GLPrintPipeline one after the other, each stage's files
/// and report.json section, and the safety gates before the machine programs.
///
/// Exit statuses (docs/user-guide.md, "What the exit statuses mean"):
///   0  every requested output written;
///   1  an error (bad input, a failing stage): one line on stderr, report.json names the stage;
///   2  bad usage (unknown option, malformed value), nothing written;
///   4  gate: the toolpath collides (nozzle or plate): inspection outputs written, no program;
///   5  gate: toolpath points the robot cannot reach: no program;
///   6  gate: a joint flip or joint limit the cell layout search could not avoid: no program;
///   130 interrupted by Ctrl-C: the running stage stopped, report.json names it.
/// (3 is `geolattice verify`'s collision status.) A gate prints exactly one line on stderr.

namespace geolattice {

enum ExitStatus {
  kExitOk = 0,
  kExitError = 1,
  kExitUsage = 2,
  kExitVerifyCollision = 3,
  kExitCollisionGate = 4,
  kExitUnreachableGate = 5,
  kExitJointGate = 6,
  kExitInterrupted = 130
};

/// Runs `geolattice run ...` (argv[1] == "run"); returns the exit status. Throws UsageError for
/// bad usage and GeoLatticeError for a failing stage (after writing report.json).
int runRunCommand(int argc, char** argv);

}  // namespace geolattice
