#include "CliOptions.h"
#include "CliOptionTable.h"

#include "GLPrintPipeline.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <regex>
#include <sstream>

namespace geolattice {

double parseNumber(const std::string& flag, const std::string& text) {
  char* end = nullptr;
  const double v = std::strtod(text.c_str(), &end);
  if (text.empty() || *end != '\0' || !std::isfinite(v)) {
    throw UsageError(flag + " expects a number, got '" + text + "'");
  }
  return v;
}

std::vector<double> parseNumbers(const std::string& flag, const std::string& text, size_t count,
                                 const char* form) {
  std::vector<double> out;
  std::stringstream ss(text);
  std::string part;
  while (std::getline(ss, part, ',')) {
    char* end = nullptr;
    const double v = std::strtod(part.c_str(), &end);
    if (part.empty() || *end != '\0' || !std::isfinite(v) || out.size() == count) {
      throw UsageError(flag + " expects " + form + ", got '" + text + "'");
    }
    out.push_back(v);
  }
  if (out.size() != count || (!text.empty() && text.back() == ',')) {
    throw UsageError(flag + " expects " + form + ", got '" + text + "'");
  }
  return out;
}

namespace {

using namespace cli;

std::vector<CliOption> makeTable() {
  std::vector<CliOption> t;
  addModelOptions(t);
  addPrintOptions(t);
  addProgramOptions(t);
  return t;
}

const CliOption* findOption(const std::string& flag) {
  const std::string name = flag == "--output" ? "-o" : flag == "--quiet" ? "-q" : flag;
  for (const CliOption& o : runOptionTable()) {
    if (name == o.flag) {
      return &o;
    }
  }
  return nullptr;
}

}  // namespace

const std::vector<CliOption>& runOptionTable() {
  static const std::vector<CliOption> table = makeTable();
  return table;
}

void parseRunArguments(int argc, char** argv, GLPrintPipeline& pipeline, RunOptions& run) {
  if (argc < 2) {
    throw UsageError("missing command (try --help)");
  }
  if (std::string(argv[1]) != "run") {
    throw UsageError("unknown command '" + std::string(argv[1]) + "' (try --help)");
  }
  for (int i = 2; i < argc; ++i) {
    const std::string arg = argv[i];
    if (const CliOption* o = findOption(arg)) {
      std::string value;
      if (*o->value) {
        if (i + 1 >= argc) {
          throw UsageError(arg + " needs a value");
        }
        value = argv[++i];
      }
      o->set(pipeline, run, value);
    } else if (!arg.empty() && arg[0] == '-') {
      throw UsageError("unknown option " + arg);
    } else if (run.model.empty()) {
      run.model = arg;
    } else {
      throw UsageError("unexpected argument '" + arg + "'");
    }
  }
  if (run.model.empty()) {
    throw UsageError("missing MODEL");
  }
  if (run.outDir.empty()) {
    throw UsageError("missing -o OUTDIR");
  }
  if (!run.firstLayerGiven) {
    pipeline.Slicer->SetFirstLayerOffset(pipeline.Slicer->GetLayerInterval());
  }
}

std::string usageText() {
  GLPrintPipeline defaults;
  const RunOptions run;
  std::ostringstream s;
  const char* section = "";
  for (const CliOption& o : runOptionTable()) {
    if (std::string(section) != o.section) {
      section = o.section;
      s << " " << section << ":\n";
    }
    std::string head = std::string("  ") + o.flag + (*o.value ? std::string(" ") + o.value : "");
    if (std::string(o.flag) == "-o") {
      head = "  -o, --output DIR";
    }
    std::stringstream help(o.help);
    std::string line;
    bool first = true;
    while (std::getline(help, line)) {
      s << (first ? head : std::string())
        << std::string(first && head.size() < 26 ? 26 - head.size()
                       : first                   ? 1
                                                 : 26,
                       ' ')
        << line;
      first = false;
      if (help.peek() != EOF) {
        s << "\n";
      }
    }
    const std::string value = o.current(defaults, run);
    if (!value.empty() && std::string(o.flag) != "-o") {
      s << "  [" << value << "]";
    }
    s << "\n";
  }
  return s.str();
}

std::string optionListing() {
  GLPrintPipeline defaults;
  const RunOptions run;
  std::ostringstream s;
  for (const CliOption& o : runOptionTable()) {
    s << o.flag << '\t' << o.property << '\t' << o.current(defaults, run) << '\n';
  }
  return s.str();
}

std::string withFlagNames(const std::string& message) {
  std::string out = message;
  for (const CliOption& o : runOptionTable()) {
    const size_t dot = o.property.find('.');
    if (dot == std::string::npos || o.flag[0] != '-' || o.flag[1] != '-') {
      continue;
    }
    const std::string property = o.property.substr(dot + 1);
    // The first flag that sets a property names it (e.g. AlphaWidth -> --lattice-width is listed
    // first, but --alpha-width is the exact one: prefer an option whose flag spells the property).
    out = std::regex_replace(out, std::regex("\\b" + property + "\\b"), o.flag);
  }
  return out;
}

}  // namespace geolattice
