#pragma once
/// @file CliOptionTable.h
/// @brief Internal to the CLI: the helpers the option table is written with (number options bound
/// to a filter's setter and getter, choices, whole numbers, the pipeline's filters by role) and
/// the table's parts, one per group of stages (CliOptionsModel.cxx: placement to layers;
/// CliOptionsPrint.cxx: lattice, sequence, nozzle and toolpath; CliOptionsProgram.cxx: the robot
/// and G-code programs). CliOptions.cxx joins them in --help order.
#include "CliOptions.h"

#include "GLPrintPipeline.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <string>
#include <vector>

namespace geolattice::cli {
using P = GLPrintPipeline;
using Setter = std::function<void(P&, RunOptions&, const std::string&)>;
using Getter = std::function<std::string(P&, const RunOptions&)>;

inline std::string text(double v) {
  std::ostringstream s;
  s << v;
  return s.str();
}
inline std::string text(const double* v, int n) {
  std::string s;
  for (int k = 0; k < n; ++k) {
    s += (k ? "," : "") + text(v[k]);
  }
  return s;
}

/// A whole number in [lo, hi] or UsageError.
inline long long wholeNumber(const std::string& flag, const std::string& value, double lo,
                             double hi) {
  const double v = parseNumber(flag, value);
  if (v < lo || v > hi || v != std::floor(v)) {
    throw UsageError(flag + " expects a whole number from " + text(lo) + " to " + text(hi) +
                     ", got '" + value + "'");
  }
  return static_cast<long long>(v);
}

/// One of `names` (its index) or UsageError.
inline int choice(const std::string& flag, const std::string& value,
                  const std::vector<std::string>& names) {
  const auto it = std::find(names.begin(), names.end(), value);
  if (it == names.end()) {
    std::string list;
    for (size_t k = 0; k < names.size(); ++k) {
      list += (k ? (k + 1 == names.size() ? " or " : ", ") : "") + names[k];
    }
    throw UsageError(flag + " must be " + list + " (got '" + value + "')");
  }
  return static_cast<int>(it - names.begin());
}

/// A number option bound to `set`/`get` of one filter (the getter gives the default).
template <class F>
CliOption number(const char* flag, const char* value, const char* section, const char* help,
                 const std::string& property, vtkNew<F> P::*filter, void (F::*set)(double),
                 double (F::*get)()) {
  return {
      flag,
      value,
      section,
      help,
      property,
      [=](P& p, RunOptions&, const std::string& v) { ((p.*filter)->*set)(parseNumber(flag, v)); },
      [=](P& p, const RunOptions&) {
        return text(((p.*filter)->*get)());
      }};
}

/// A whole-number option in [lo, hi] bound to `set`/`get` of one filter (the getter gives the
/// default).
template <class F, class T>
CliOption integer(const char* flag, const char* value, const char* section, const char* help,
                  const std::string& property, vtkNew<F> P::*filter, void (F::*set)(T),
                  T (F::*get)(), double lo, double hi) {
  return {flag,
          value,
          section,
          help,
          property,
          [=](P& p, RunOptions&, const std::string& v) {
            ((p.*filter)->*set)(static_cast<T>(wholeNumber(flag, v, lo, hi)));
          },
          [=](P& p, const RunOptions&) {
            return std::to_string(static_cast<long long>(((p.*filter)->*get)()));
          }};
}

/// A flag without a value that sets one filter's boolean property to `to`; the option listing
/// shows the filter's value as `onWord` or `offWord` (the getter gives the default).
template <class F, class Set, class Get>
CliOption toggle(const char* flag, const char* section, const char* help,
                 const std::string& property, vtkNew<F> P::*filter, Set set, Get get, bool to,
                 const char* onWord = "on", const char* offWord = "off") {
  return {flag,
          "",
          section,
          help,
          property,
          [=](P& p, RunOptions&, const std::string&) { ((p.*filter)->*set)(to); },
          [=](P& p, const RunOptions&) {
            return std::string(((p.*filter)->*get)() ? onWord : offWord);
          }};
}

inline const char* const kStageNames =
    "mesh | gdf | layers | lattice | sequence | toolpath | program";
inline const std::vector<std::string> kStages = {"mesh",     "gdf",      "layers", "lattice",
                                                 "sequence", "toolpath", "program"};
inline const std::vector<std::string> kStrategies = {"lpt", "dpt", "a4",
                                                     "best"};  // = Strategy 0..3

/// The table's parts, in --help order.
void addModelOptions(std::vector<CliOption>& t);
void addPrintOptions(std::vector<CliOption>& t);
void addProgramOptions(std::vector<CliOption>& t);

}  // namespace geolattice::cli
