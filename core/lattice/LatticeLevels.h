#pragma once
/// @file LatticeLevels.h
/// @brief The iso-values Ψ^α, Ψ^β of the lattice lines (paper Section 2.2): evenly spaced
/// levels φ_j = j·w + phase, or graded levels whose spacing follows a per-point width scale.
///
/// Data flow: α (or β) at every layer point (+ optional width scale per point) -> sorted level
/// values -> LatticeGraph (isolines α = level on every layer).
///
/// Graded lattice (beyond the paper, whose Fig. 24 (b) only shows the idea): the lattice lines
/// must stay α- and β-isolines so that they stay orthogonal to the layer normal ∇γ (the
/// self-supporting property) and so that the same line continues from layer to layer (a wall
/// of the infill). Only the spacing of the levels may vary. We remap each field by a monotone
/// 1-D function G (mm -> mm):
///     G(f) = f_min + ∫_{f_min}^{f} dx / s̄(x),   levels: G(f) = phase + j·w,
/// so the distance between neighbouring lines is w·s̄(f). s̄(f) is the smallest width scale s
/// of the layer points whose field value lies within the same bin of width h = w·s_min / 8
/// around f (8 bins per finest line spacing; empty bins take the value of the nearest non-empty
/// bin, the smaller one on a tie). Taking the minimum makes the lattice at least as dense as
/// requested everywhere along a line, at the price that a small dense region densifies the
/// whole strip of lines through it (a line cannot be dense in one place and sparse in another
/// and remain an isoline). With s ≡ 1, G is the identity and the levels are the uniform ones.
#include <vector>

namespace geolattice {

/// More levels than this per field are refused (the width is then far too small for the part).
constexpr int kMaxLatticeLevels = 1000000;
/// Bins per finest line spacing when sampling the width scale of a graded lattice.
constexpr int kGradingBinsPerSpacing = 8;

/// Levels φ_j = phase + j·width (j integer) with lo < φ_j <= hi, ascending. A level equal to
/// lo is left out: the isoline of the field's minimum is empty (an exact hit counts as above).
/// @throws GeoLatticeError if width <= 0 or non-finite, phase or lo/hi non-finite, lo > hi, or
///   more than kMaxLatticeLevels levels.
std::vector<double> uniformLatticeLevels(double lo, double hi, double width, double phase);

/// Graded levels (see the file comment) from the field values f (one per layer point) and the
/// width scale s (one per layer point, > 0): levels f_min < φ_j <= f_max, strictly ascending.
/// @throws GeoLatticeError for a width <= 0, sizes that differ, a non-finite f, or an s that is
///   not finite and > 0 (naming the first offending point), or too many levels.
std::vector<double> gradedLatticeLevels(const std::vector<double>& f,
                                        const std::vector<double>& scale, double width,
                                        double phase);

}  // namespace geolattice
