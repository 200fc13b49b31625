#pragma once
/// @file GLPrintheadFile.h
/// @brief Reads a printhead mesh file (GL Nozzle's PrintheadFile, the CLI's --printhead) into
/// core's Printhead (nozzle/Printhead.h) with GL Mesh Reader's surface readers (.stl .obj .ply
/// .vtp .off). A printhead is read and validated once per file version: the result is kept by
/// path, size and modification time, so the sequencer, the verifiers and the toolpath planner
/// of one pipeline share it and a changed file is read again.
#include "nozzle/Printhead.h"

#include <memory>
#include <string>

namespace geolattice {

/// Throws GeoLatticeError naming the file and the problem (missing, unreadable, not a closed
/// manifold, tip not at the origin, ...).
std::shared_ptr<const Printhead> readPrintheadFile(const std::string& path);

}  // namespace geolattice
