#pragma once
/// @file CliOptions.h
/// @brief The options of `geolattice run`, as one table. Each option either sets a property of a
/// filter of the pipeline (GLPrintPipeline) or a setting only the command line has (RunOptions).
/// The defaults shown by --help are read from the filters themselves, which take them from the
/// core options structs: the command line states no default of its own for a filter property.
/// `geolattice --list-options` prints the table (flag, property, default) for the defaults test.
#include <functional>
#include <stdexcept>
#include <string>
#include <vector>

class GLPrintPipeline;

namespace geolattice {

/// Bad command line: reported on one line, exit status 2.
struct UsageError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

/// Parses a finite number or throws UsageError naming the flag.
double parseNumber(const std::string& flag, const std::string& text);
/// Parses `count` comma-separated finite numbers (e.g. X,Y,Z) or throws UsageError naming the
/// flag and `form` ("X,Y,Z").
std::vector<double> parseNumbers(const std::string& flag, const std::string& text, size_t count,
                                 const char* form);

/// The settings of a run that are not filter properties, with their defaults.
struct RunOptions {
  std::string model;
  std::string outDir;
  std::string until = "program";  ///< last stage: mesh | gdf | layers | lattice | sequence |
                                  ///< toolpath | program
  bool quiet = false;
  bool firstLayerGiven = false;  ///< else the first layer is at --layer-interval
  int replaySteps = 50;          ///< files of the print replay (toolpath.pvd); 0 = none
  bool gcode = true;             ///< --gcode none: no G-code
  bool allowCollisions = false;  ///< write machine programs for a colliding toolpath anyway
  bool partOffsetGiven = false, partOnFlangeGiven = false;
};

/// One command-line option.
struct CliOption {
  const char* flag;      ///< "--nozzle-angle"
  const char* value;     ///< "DEG"; "" for a switch
  const char* section;   ///< heading of its group in --help
  const char* help;      ///< one line (more lines: '\n')
  std::string property;  ///< "GLNozzle.NozzleAngle": the proxy property it sets; "" = CLI only
  std::function<void(GLPrintPipeline&, RunOptions&, const std::string&)> set;
  /// The value in effect (on a default pipeline: the default), as --help prints it.
  std::function<std::string(GLPrintPipeline&, const RunOptions&)> current;
};

/// The table, in --help order.
const std::vector<CliOption>& runOptionTable();

/// Parses `geolattice run MODEL -o OUTDIR [options]` (argv[1] == "run") into the pipeline's
/// filters and `run`. Throws UsageError for unknown options, missing or malformed values.
void parseRunArguments(int argc, char** argv, GLPrintPipeline& pipeline, RunOptions& run);

/// The whole --help text, defaults read from a default pipeline.
std::string usageText();

/// flag<TAB>property<TAB>default, one line per option (for tests and tools).
std::string optionListing();

/// An error message of a filter with its property names replaced by the CLI flags that set them
/// ("FitSize must be >= 0" -> "--fit-size must be >= 0").
std::string withFlagNames(const std::string& message);

}  // namespace geolattice
