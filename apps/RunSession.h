#pragma once
/// @file RunSession.h
/// @brief The state of one `geolattice run` and what every stage does with it: run a stage's
/// filters with progress, Ctrl-C and error capture (Update), write files and record them, the
/// report sections, the gate lines, and report.json at the end. RunCommand.cxx walks the stages
/// with it; ProgramStage.cxx is the program stage behind its safety gates.
#include "CliOptions.h"
#include "OutputFiles.h"
#include "StageReports.h"

#include "GLPrintPipeline.h"
#include "common/BackgroundWriter.h"
#include "common/Error.h"

#include <vtkSmartPointer.h>

#include <chrono>
#include <filesystem>
#include <functional>
#include <initializer_list>
#include <string>
#include <vector>

class vtkAlgorithm;
class vtkDataObject;
class vtkWriter;

namespace geolattice {

using Clock = std::chrono::steady_clock;
double secondsSince(Clock::time_point start);

/// A stage that failed: report.json names it, stderr gets "STAGE: message".
struct StageError : GeoLatticeError {
  StageError(const std::string& stage, const std::string& message)
      : GeoLatticeError(stage + ": " + message), Stage(stage), Message(message) {}
  std::string Stage, Message;
};

class RunSession {
public:
  GLPrintPipeline P;
  RunOptions R;
  OutputRecord Files{""};
  BackgroundWriter Writer;  ///< the VTK XML files, written while the next stages run
  /// The print replay's files (the largest job, posted last): on a thread of its own beside
  /// toolpath.vtp, from a copy of its own, so the two do not queue at the end of the run.
  BackgroundWriter ReplayWriter;
  Json Report = Json::object();
  double LastSeconds = 0;

  /// The report section of a stage, with its seconds first.
  Json& Section(const char* name);
  /// Updates `last` (watching `watched`, default `last`, for errors; Ctrl-C aborts them) and
  /// returns its output. Throws StageError with the first error message when the update fails.
  vtkDataObject* Update(const char* stage, vtkAlgorithm* last,
                        std::initializer_list<vtkAlgorithm*> watched = {});
  /// The stages that can take long enough for a percentage on their line.
  static bool IsLongStage(const std::string& stage);
  /// Writes with `writer` and returns the first error reported, empty on success.
  static std::string RunWriter(vtkWriter* writer, bool percent = false);
  /// Removes program files already written (a stage leaves all its files or none).
  static void RemoveFiles(const std::vector<std::string>& files);
  /// One stderr line of a gate: "stopped: ..." or "warning: ...".
  void GateLine(const std::string& line, bool warning = false);
  /// "geolattice: note: `line`" on stderr (even with -q: about the part), once per run (the
  /// stages run again for other set-ups), or later while notes are held. Empty: nothing.
  void Note(const std::string& line);
  /// While held, notes wait: the set-up they describe may still be replaced (--orient auto's
  /// tries run the stages again for another orientation, whose mesh and fields note anew).
  /// false says the held ones.
  void HoldNotes(bool hold);
  /// Forgets the held notes: the stages run again for another set-up.
  void DropHeldNotes() { this->Held.clear(); }
  /// Writes a deep copy of `data` as OUTDIR/name (VTK XML) on the writer thread and records it.
  void Write(vtkDataObject* data, const char* name);
  /// Posts `write` to the writer thread (`replay`: to ReplayWriter) as the job of `path` (its
  /// seconds) and records the files it writes, `records`, in the order of the run; a job that
  /// fails or is skipped takes them out of the record again (WaitForFiles).
  void Post(const std::string& path, const std::vector<std::string>& records,
            std::function<void()> write, bool replay = false);
  /// Waits for the writer thread; records each file's seconds and drops the files of failed or
  /// skipped jobs from the record. Throws a failed write's error.
  void WaitForFiles();
  /// Runs write(OUTDIR/name) and records the file.
  template <class F>
  void WriteFile(const char* name, F&& write) {
    const std::string path = (std::filesystem::path(R.outDir) / name).string();
    const auto start = Clock::now();
    write(path);
    this->Files.add(path, secondsSince(start));
  }
  /// Waits for the files, moves the earlier run's leftovers to previous/, then writes report.json
  /// (every file written and its seconds, and the exit status).
  void Finish(int status);

private:
  struct PendingJob {
    std::string path;
    std::vector<std::string> records;
    bool replay = false;  ///< posted to ReplayWriter
  };
  /// Throws the error of a failed job of either writer, without waiting.
  void CheckWriters();
  std::vector<PendingJob> Pending;   ///< posted since the last WaitForFiles, in order
  std::vector<std::string> Written;  ///< files the writer thread has written in this run
  std::vector<std::string> Noted;    ///< notes said (Note)
  std::vector<std::string> Held;     ///< notes waiting while HoldNotes(true)
  bool Holding = false;
};

/// The program stage behind its gates: a colliding toolpath (unless --allow-collisions),
/// unreachable points (unless --allow-unreachable) or a joint flip/limit stop it before any
/// program file is written; the report records which gate stopped what. Returns the exit status.
int runProgramStage(RunSession& run, vtkDataObject* pathCollisions);

}  // namespace geolattice
