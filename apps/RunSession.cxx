#include "RunSession.h"

#include "CrashReport.h"
#include "ErrorCapture.h"
#include "Interrupt.h"

#include "common/AtomicFile.h"

#include <vtkAlgorithm.h>
#include <vtkCallbackCommand.h>
#include <vtkCommand.h>
#include <vtkExecutive.h>
#include <vtkDataObject.h>
#include <vtkNew.h>
#include <vtkSmartPointer.h>
#include <vtkWriter.h>

#include <algorithm>
#include <fstream>
#include <iostream>
#include <system_error>
#include <utility>

namespace geolattice {

namespace {

namespace fs = std::filesystem;

/// While alive, prints " 25%", " 50%", " 75%" on the current stage line as the progress events of
/// `algorithm` pass them (nothing when disabled, e.g. with -q).
class ProgressPrinter {
public:
  ProgressPrinter(vtkAlgorithm* algorithm, bool enabled)
      : Algorithm(enabled ? algorithm : nullptr) {
    if (this->Algorithm) {
      this->Command->SetClientData(&this->Next);
      this->Command->SetCallback([](vtkObject*, unsigned long, void* client, void* call) {
        int& next = *static_cast<int*>(client);
        const double p = call ? *static_cast<double*>(call) : 0.0;
        for (; next <= 3 && p >= 0.25 * next; ++next) {
          std::cout << " " << 25 * next << "%" << std::flush;
        }
      });
      this->Tag = this->Algorithm->AddObserver(vtkCommand::ProgressEvent, this->Command);
    }
  }
  ~ProgressPrinter() {
    if (this->Algorithm) {
      this->Algorithm->RemoveObserver(this->Tag);
    }
  }
  ProgressPrinter(const ProgressPrinter&) = delete;
  ProgressPrinter& operator=(const ProgressPrinter&) = delete;

private:
  vtkAlgorithm* Algorithm;
  vtkNew<vtkCallbackCommand> Command;
  unsigned long Tag = 0;
  int Next = 1;  ///< the next quarter to print
};

}  // namespace

double secondsSince(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

/// The report section of a stage, with its seconds first.
Json& RunSession::Section(const char* name) {
  Json& s = this->Report[name];
  s["seconds"] = this->LastSeconds;
  return s;
}

/// Updates `last` (watching `watched`, default `last`, for errors) and returns its output.
/// Throws StageError with the first error message when the update fails.
vtkDataObject* RunSession::Update(const char* stage, vtkAlgorithm* last,
                                  std::initializer_list<vtkAlgorithm*> watched) {
  this->CheckWriters();  // a file of an earlier stage could not be written: stop here
  setCrashStage(stage);
  if (!R.quiet) {
    std::cout << "geolattice: " << stage << " ..." << std::flush;
  }
  ErrorCapture errors;
  for (vtkAlgorithm* a : watched) {
    errors.Watch(a);
  }
  if (watched.size() == 0) {
    errors.Watch(last);
  }
  const auto start = Clock::now();
  int ok = 0;
  {
    const ProgressPrinter percent(last, !R.quiet && IsLongStage(stage));
    std::vector<vtkAlgorithm*> stageFilters(watched);
    if (stageFilters.empty()) {
      stageFilters.push_back(last);
    }
    const AbortOnInterrupt abort(stageFilters);
    ok = last->GetExecutive()->Update();
  }
  if (InterruptHandler::Interrupted()) {
    throw StageError(stage, "interrupted");
  }
  this->LastSeconds = secondsSince(start);
  if (!R.quiet) {
    std::cout << (ok && errors.Message.empty() ? " done" : " failed") << " (" << this->LastSeconds
              << " s)\n";
  }
  if (!ok || !errors.Message.empty()) {
    throw StageError(stage, errors.Message.empty() ? std::string(last->GetClassName()) + " failed"
                                                   : errors.Message);
  }
  return last->GetOutputDataObject(0);
}

/// The stages that can take long enough for a percentage on their line.
bool RunSession::IsLongStage(const std::string& stage) {
  return stage == "mesh" || stage == "gdf" || stage == "lattice" || stage == "sequence" ||
         stage == "toolpath";
}

/// Writes with `writer` and returns the first error reported, empty on success.
std::string RunSession::RunWriter(vtkWriter* writer, bool percent) {
  ErrorCapture errors;
  errors.Watch(writer);
  const ProgressPrinter printer(writer, percent);
  const AbortOnInterrupt abort({writer});
  const int ok = writer->Write();
  if (InterruptHandler::Interrupted()) {
    throw StageError("program", "interrupted");  // the writers run in the program stage
  }
  if (errors.Message.empty() && !ok) {
    errors.Message = std::string(writer->GetClassName()) + " failed";
  }
  return errors.Message;
}

/// Removes program files already written: a later writer of the stage failed, and the stage
/// leaves all its files or none.
void RunSession::RemoveFiles(const std::vector<std::string>& files) {
  std::error_code ec;
  for (const std::string& f : files) {
    fs::remove(f, ec);
  }
}

void RunSession::Note(const std::string& line) {
  auto in = [&line](const std::vector<std::string>& lines) {
    return std::find(lines.begin(), lines.end(), line) != lines.end();
  };
  if (line.empty() || in(this->Noted) || in(this->Held)) {
    return;
  }
  if (this->Holding) {
    this->Held.push_back(line);
    return;
  }
  this->Noted.push_back(line);
  std::cerr << "geolattice: note: " << line << "\n";
}

void RunSession::HoldNotes(bool hold) {
  this->Holding = hold;
  if (!hold) {
    const std::vector<std::string> held = std::move(this->Held);
    this->Held.clear();
    for (const std::string& line : held) {
      this->Note(line);
    }
  }
}

void RunSession::GateLine(const std::string& line, bool warning) {
  std::cerr << "geolattice: " << (warning ? "warning: " : "stopped: ") << line << "\n";
}

void RunSession::Write(vtkDataObject* data, const char* name) {
  const std::string path = (fs::path(R.outDir) / name).string();
  if (!data) {
    throw GeoLatticeError("cannot write a null data object to " + path);
  }
  vtkSmartPointer<vtkDataObject> copy = vtk::TakeSmartPointer(data->NewInstance());
  copy->DeepCopy(data);  // the pipeline goes on (and may run the stage again) meanwhile
  // Moved: the job holds the copy's only reference (BackgroundWriter.h).
  this->Post(path, {path}, [copy = std::move(copy), path] { writeVtkXml(copy, path); });
}

void RunSession::CheckWriters() {
  this->Writer.check();
  this->ReplayWriter.check();
}

void RunSession::Post(const std::string& path, const std::vector<std::string>& records,
                      std::function<void()> write, bool replay) {
  this->CheckWriters();  // a file before it could not be written: the run stops here
  for (const std::string& f : records) {
    this->Files.add(f, 0.0);  // its place in the list now, its seconds when written
  }
  this->Pending.push_back({path, records, replay});
  (replay ? this->ReplayWriter : this->Writer).post(path, std::move(write));
}

void RunSession::WaitForFiles() {
  // Each writer finishes its jobs in the order posted: the first done.size() of its jobs were
  // written, the others failed or were skipped, and their files (unless an earlier job wrote the
  // same one) are not this run's. The first error (of the main writer first) is thrown.
  std::vector<std::pair<std::string, double>> done[2];
  std::exception_ptr error;
  BackgroundWriter* writers[2] = {&this->Writer, &this->ReplayWriter};
  for (int w = 0; w < 2; ++w) {
    try {
      done[w] = writers[w]->wait();
    } catch (...) {
      if (!error) {
        error = std::current_exception();
      }
      done[w] = writers[w]->finished();
    }
  }
  size_t next[2] = {0, 0};  // of each writer: its next job's index in done[]
  for (size_t k = 0; k < this->Pending.size(); ++k) {
    const PendingJob& job = this->Pending[k];
    const int w = job.replay ? 1 : 0;
    const size_t j = next[w]++;
    if (j < done[w].size()) {
      this->Written.insert(this->Written.end(), job.records.begin(), job.records.end());
      if (!job.path.empty()) {
        this->Files.add(job.path, done[w][j].second);
      }
      continue;
    }
    for (const std::string& f : job.records) {
      if (std::find(this->Written.begin(), this->Written.end(), f) == this->Written.end()) {
        this->Files.remove(f);
      }
    }
  }
  this->Pending.clear();
  if (error) {
    std::rethrow_exception(error);
  }
}

/// Waits for the files, moves the earlier run's leftovers to previous/, then writes report.json
/// (with every file written and its seconds, and the exit status).
void RunSession::Finish(int status) {
  try {
    this->WaitForFiles();
  } catch (const std::exception& e) {
    if (!this->Report.contains("failed")) {
      throw;  // the run fails with it
    }
    std::cerr << "geolattice: " << e.what() << "\n";  // the run failed before: report that
  }
  const std::vector<std::string> retired = this->Files.retireStaleOutputs();
  Json files = Json::array();
  for (const auto& [name, seconds] : this->Files.files()) {
    files.push_back({{"file", name}, {"seconds", seconds}});
  }
  this->Report["files"] = files;
  if (!retired.empty()) {
    this->Report["previous"] = retired;
  }
  this->Report["exit_status"] = status;
  const std::string path = (fs::path(R.outDir) / "report.json").string();
  writeAtomically(path, [this](const std::string& tmp) {
    std::ofstream out(tmp);
    out << this->Report.dump(2) << "\n";
    return static_cast<bool>(out);
  });
  if (!R.quiet) {
    std::cout << "geolattice: wrote " << this->Files.files().size() + 1 << " files in " << R.outDir
              << " (report.json lists them)";
    if (!retired.empty()) {
      std::cout << "; " << retired.size() << " files of an earlier run moved to " << R.outDir
                << "/previous";
    }
    // The toolpath, or the furthest stage's file a failed run wrote (none: report.json only).
    std::string view;
    for (const auto& [name, seconds] : this->Files.files()) {
      const std::string ext = fs::path(name).extension().string();
      if ((ext == ".vtp" || ext == ".vtu") && view != "toolpath.vtp") {
        view = fs::path(name).filename().string();
      }
    }
    std::cout << "\n";
    if (!view.empty()) {
      std::cout << "geolattice: open them in ParaView (paraview " << R.outDir << "/" << view
                << ") or load the plugin for the filters.\n";
    }
  }
}

}  // namespace geolattice
