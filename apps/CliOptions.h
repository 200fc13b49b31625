#pragma once
/// @file CliOptions.h
/// @brief Command-line pieces shared by `geolattice run` and `geolattice verify`: usage errors,
/// number parsing and the nozzle options that both the sequencer and the verifier take.
#include "JsonWriter.h"

#include <functional>
#include <stdexcept>
#include <string>

namespace geolattice {

/// Bad command line: reported on one line, exit status 2.
struct UsageError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

/// Parses a finite number or throws UsageError naming the flag.
double parseNumber(const std::string& flag, const std::string& text);

/// @brief Nozzle model and material sampling (core/sequence/NozzleModel.h); 0 length = cone only.
struct NozzleOptions {
  double angle = 45.0;
  double length = 0.0;
  double holderRadius = 0.0;
  double tipClearance = 0.0;
  double sampleSpacing = 1.0;

  /// Consumes --nozzle-angle, --nozzle-length, --holder-radius, --tip-clearance and
  /// --sample-spacing (value() returns the option's argument); false for any other flag.
  bool parse(const std::string& flag, const std::function<std::string()>& value);

  /// Sets the same-named properties of vtkGLPrintSequencer or vtkGLCollisionVerifier.
  template <class Filter>
  void apply(Filter* f) const {
    f->SetNozzleAngle(angle);
    f->SetNozzleLength(length);
    f->SetHolderRadius(holderRadius);
    f->SetTipClearance(tipClearance);
    f->SetSampleSpacing(sampleSpacing);
  }

  /// Writes nozzle_angle_deg, nozzle_length_mm, holder_radius_mm, tip_clearance_mm and
  /// sample_spacing_mm into a report section.
  void report(JsonObject& section) const;
};

} // namespace geolattice
