// geolattice: the command-line front end. `run` builds the same VTK pipeline as the ParaView
// plugin (filters/GLPrintPipeline.h) and writes every stage's output plus report.json into the
// output directory; `verify` re-checks a saved result for nozzle collisions.
#include "CliOptions.h"
#include "CrashReport.h"
#include "GLPrintPipeline.h"
#include "RunCommand.h"
#include "VerifyCommand.h"
#include "vtkGLPrintPart.h"

#include <vtkAlgorithm.h>
#include <vtkAlgorithmOutput.h>
#include <vtkLogger.h>
#include <vtkNew.h>
#include <vtkOutputWindow.h>

#include <cstdlib>
#include <cstring>
#include <iostream>
#include <string>

#include <sys/auxv.h>
#include <unistd.h>

namespace {

const char* kHead =
    R"(geolattice - multi-axis support-free printing with lattice infill (GeoLattice )" GEOLATTICE_VERSION
    R"()

Usage:
  geolattice run MODEL -o OUTDIR [options]
  geolattice verify OUTDIR [nozzle options] [--allow-unavoidable]
  geolattice --help | --version | --list-options

MODEL is a closed triangle surface (.stl .obj .ply .vtp .off) or a tet mesh (.vtu .tet .node
.ele; a tet mesh skips meshing). Outputs in OUTDIR (docs/user-guide.md describes each):
tets.vtu, fields.vtu (Gamma, Alpha, Beta), layers.vtp, overhang.vtp, lattice.vtp, skeleton.vtp,
sequence.vtp, sequence.csv, collisions.vtp, toolpath.vtp, toolpath_collisions.vtp, toolpath.pvd
(the print replay), the machine programs print_part.script (+ print_part_1.script, ... when
split; URScript for a UR5/UR5e holding the part under a fixed nozzle), toolpath.gcode (5-axis
G-code for an A-C or B-C table) and waypoints.csv, and report.json (per stage: seconds, counts,
results; the files written; which safety gate stopped what). Every file is written to a temporary
name first, so nothing partial is left behind; files of an earlier run that this run does not
write again are moved to OUTDIR/previous/.

Machine programs are written only for a toolpath the collision verifier passes (nozzle and
build plate), that the robot reaches, without a joint flip; otherwise the inspection outputs are
written, one line on stderr says why, and the exit status names the gate.

`verify OUTDIR` re-checks with the independent collision verifier the newer of toolpath.vtp
(every point at its own time) and lattice.vtp (sub-graphs at their PrintOrder), nozzle from
report.json unless given; exit status 0 when collision-free, 3 when the nozzle hits earlier
material (with --allow-unavoidable: only when an order could have avoided it).

Options of run (defaults in brackets, read from the filters):
)";

const char* kTail = R"(
Exit status: 0 success; 1 an error (one line on stderr naming the problem; report.json names
the stage); 2 bad usage; 3 (verify) a collision; 4 the toolpath collides: no program written
(--allow-collisions); 5 unreachable toolpath points: no program (--allow-unreachable); 6 a joint
flip or joint limit the cell layout search could not avoid: no program.
)";

/// Swallows VTK's console output; the messages that matter reach the CLI through ErrorCapture.
class SilentOutputWindow : public vtkOutputWindow {
public:
  static SilentOutputWindow* New() { return new SilentOutputWindow; }
  vtkTypeMacro(SilentOutputWindow, vtkOutputWindow);
  void DisplayText(const char*) override {}
};

/// "== CLASS" and the PrintSelf of a default-constructed object, for every filter and writer.
void printFilterDefaults() {
  GLPrintPipeline p;
  vtkObject* objects[] = {p.Nozzle,           p.Reader,         p.Placement,      p.Orientation,
                          p.Pedestal,         p.Tetrahedralize, p.GeodesicFields, p.Slicer,
                          p.OverhangAnalysis, p.LatticeInfill,  p.SkeletonTree,   p.Sequencer,
                          p.SequenceVerifier, p.Planner,        p.ScriptWriter,   p.GCodeWriter,
                          p.WaypointWriter,   p.ToolpathReplay, p.PrintSummary};
  vtkNew<vtkGLPrintPart> part;
  for (vtkObject* o : objects) {
    std::cout << "== " << o->GetClassName() << "\n";
    o->Print(std::cout);
  }
  std::cout << "== " << part->GetClassName() << "\n";
  part->Print(std::cout);
}

/// One line per stage: name, class, and per input port the producing stage and its output port.
void describePipeline() {
  GLPrintPipeline p;
  for (int s = 0; s < GLPrintPipeline::NumberOfStages; ++s) {
    vtkAlgorithm* a = p.Filter(static_cast<GLPrintPipeline::Stage>(s));
    std::cout << GLPrintPipeline::StageName(static_cast<GLPrintPipeline::Stage>(s)) << '\t'
              << a->GetClassName();
    for (int port = 0; port < a->GetNumberOfInputPorts(); ++port) {
      vtkAlgorithmOutput* in = a->GetInputConnection(port, 0);
      for (int t = 0; in && t < GLPrintPipeline::NumberOfStages; ++t) {
        if (p.Filter(static_cast<GLPrintPipeline::Stage>(t)) == in->GetProducer()) {
          std::cout << '\t' << port << ':'
                    << GLPrintPipeline::StageName(static_cast<GLPrintPipeline::Stage>(t)) << '.'
                    << in->GetIndex();
        }
      }
    }
    std::cout << '\n';
  }
}

}  // namespace

namespace {

/// Starts the program again with glibc's malloc on transparent huge pages (the tunable
/// glibc.malloc.hugetlb is read only at start-up): on this kernel's default ("madvise") the
/// large arrays of a run then fault in 2 MiB at a time, not 4 KiB. Measured: a 1M-tet run takes
/// 0.98M -> 0.11M page faults (43.7 -> 38.5 s), the 80 mm bunny 128k -> 41k (0.3-1.5 s less
/// than its 6.6-7.9 s), for ~10 MB more memory and one more start (0.07 s).
///
/// And with the memory a stage frees kept for the next one: by default glibc maps every block
/// above 128 KiB (its threshold then grows with what is freed) on its own and returns it when
/// freed, gives the top of the heap back above 128 KiB free, and grows the heap in small
/// steps, so each stage's arrays were fresh pages the kernel zeroes (11 % of topopt's CPU time
/// in page faults and clear_page). Blocks up to 32 MiB (glibc's largest threshold) now come
/// from the heap, which grows 64 MiB at a time and is not trimmed: topopt 57k -> 4.8k page
/// faults, 10.8 -> 10.2 CPU s, ~15 MB more peak memory. A tunable the user set already is kept
/// (all of them when glibc.malloc.hugetlb is set); when the restart fails the run goes on.
void restartOnHugePages(char** argv) {
  const char* tunables = std::getenv("GLIBC_TUNABLES");
  // Once only (a marker, in case the loader drops the tunable), and never for a setuid start
  // (the loader ignores tunables there).
  if ((tunables && std::strstr(tunables, "glibc.malloc.hugetlb")) ||
      std::getenv("GEOLATTICE_RESTARTED") || ::getauxval(AT_SECURE) != 0) {
    return;
  }
  const std::string old = tunables ? tunables : "";
  std::string value = old;
  for (const char* tunable :
       {"glibc.malloc.hugetlb=1", "glibc.malloc.mmap_threshold=33554432",
        "glibc.malloc.trim_threshold=4294967296", "glibc.malloc.top_pad=67108864"}) {
    const std::string name(tunable, std::strchr(tunable, '=') + 1);
    if (old.find(name) == std::string::npos) {
      value += (value.empty() ? "" : ":") + std::string(tunable);
    }
  }
  if (::setenv("GLIBC_TUNABLES", value.c_str(), 1) == 0 &&
      ::setenv("GEOLATTICE_RESTARTED", "1", 1) == 0) {
    ::execv("/proc/self/exe", argv);
  }
  // Not restarted: the environment as it was.
  ::unsetenv("GEOLATTICE_RESTARTED");
  if (tunables) {
    ::setenv("GLIBC_TUNABLES", old.c_str(), 1);
  } else {
    ::unsetenv("GLIBC_TUNABLES");
  }
}

}  // namespace

int main(int argc, char** argv) {
  if (argc >= 2 && (!std::strcmp(argv[1], "run") || !std::strcmp(argv[1], "verify"))) {
    restartOnHugePages(argv);
  }
  for (int i = 1; i < argc; ++i) {
    if (!std::strcmp(argv[i], "--help") || !std::strcmp(argv[i], "-h")) {
      std::cout << kHead << geolattice::usageText() << kTail;
      return 0;
    }
    if (!std::strcmp(argv[i], "--version")) {
      std::cout << "geolattice " << GEOLATTICE_VERSION << "\n";
      return 0;
    }
    if (!std::strcmp(argv[i], "--list-options")) {
      std::cout << geolattice::optionListing();
      return 0;
    }
    if (!std::strcmp(argv[i], "--describe-pipeline")) {
      describePipeline();  // for tests/pvpython/test_pipeline_description.py
      return 0;
    }
    if (!std::strcmp(argv[i], "--print-filter-defaults")) {
      printFilterDefaults();  // for tests/pvpython/test_defaults.py
      return 0;
    }
  }
  // Errors reach the user as one line through ErrorCapture; VTK's own console output (the output
  // window, and the logger that prints the executive's "returned failure" dump) stays quiet.
  geolattice::installCrashReport();
  vtkNew<SilentOutputWindow> silent;
  vtkOutputWindow::SetInstance(silent);
  vtkLogger::SetStderrVerbosity(vtkLogger::VERBOSITY_OFF);
  try {
    if (argc >= 2 && !std::strcmp(argv[1], "verify")) {
      return geolattice::runVerifyCommand(argc, argv);
    }
    return geolattice::runRunCommand(argc, argv);
  } catch (const geolattice::UsageError& e) {
    std::cerr << "geolattice: " << e.what() << "\n";
    return geolattice::kExitUsage;
  } catch (const std::exception& e) {
    std::cerr << "geolattice: error: " << e.what() << "\n";
    return geolattice::kExitError;
  }
}
