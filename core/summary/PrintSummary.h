#pragma once
/// @file PrintSummary.h
/// @brief The numbers a slicer shows before printing (issue 20, "a summary a user can read"): layers,
/// sub-graphs, lengths, an estimated print time, filament length and mass, from a planned toolpath.
///
/// The print time is the toolpath's own: the sum over its moves of length / feed rate (the move
/// ending at point i is printed at feedRate[i]), without acceleration or the robot's blending, so a
/// lower bound of the machine's time (the URScript writer reports the robot program's duration).
/// The filament mass is the filament length times its cross-section times the density.
#include <array>
#include <vector>

namespace geolattice {

struct PrintSummaryOptions {
  double filamentDensity = 1.24;  ///< g/cm³ (PLA 1.24, PETG 1.27, ABS 1.04; > 0)
  /// Throws GeoLatticeError naming a bad option.
  void validate() const;
};

/// The toolpath as plain arrays, in printing order (the planner's output point arrays).
struct PrintSummaryInput {
  std::vector<std::array<double, 3>> points;  ///< mm
  std::vector<double> feedRate;               ///< mm/s of the move ending at each point
  std::vector<int> moveKind;                  ///< MoveKind: 0 print, 1 perimeter, 2 air
  std::vector<int> layer;                     ///< lattice layer id (-1 on air moves)
  std::vector<int> subgraph;                  ///< sub-graph id (-1 on air moves)
  double filamentLength = 0.0;                ///< mm (the last cumulative extrusion value)
  double filamentDiameter = 1.75;             ///< mm
};

struct PrintSummary {
  int layers = 0;               ///< distinct layer ids >= 0 printed
  int subgraphs = 0;            ///< distinct sub-graph ids >= 0 printed
  long long points = 0;         ///< toolpath points
  double printLength = 0.0;     ///< mm of print and perimeter moves
  double airLength = 0.0;       ///< mm of air moves
  double printSeconds = 0.0;    ///< Σ length / feed rate over print and perimeter moves
  double airSeconds = 0.0;      ///< the same over air moves
  double filamentLength = 0.0;  ///< mm
  double filamentMass = 0.0;    ///< g
};

/// The summary of a toolpath. Throws GeoLatticeError when the arrays' lengths differ or a move
/// has a feed rate that is not > 0.
PrintSummary summarizePrint(const PrintSummaryInput& input, const PrintSummaryOptions& options);

}  // namespace geolattice
