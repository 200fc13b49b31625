#include "tetrahedralize/TetGenRunner.h"

#include "common/Error.h"
#include "mesh/SurfaceWrap.h"

#include <tetgen.h>

#include <cerrno>
#include <chrono>
#include <cstdint>
#include <cstring>
#include <exception>
#include <fstream>
#include <iterator>
#include <new>
#include <sstream>
#include <string>
#include <vector>

#include <fcntl.h>
#include <poll.h>
#include <pthread.h>
#include <sys/mman.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

namespace geolattice {

namespace {

// Child -> parent message header; arrays follow (points: 3 doubles each, tets: 4 int32 each,
// regions: 1 int32 per tet when hasRegions).
enum Status : int32_t {
  kOk = 0,
  kTetgenError = 1,
  kSelfIntersecting = 2,
  kOutOfMemory = 3,
  kOtherException = 4
};
struct Header {
  int32_t status;
  int32_t code;  // TetGen error code, or the number of intersecting facets
  int64_t pointCount;
  int64_t tetCount;
  int32_t hasRegions;
  int32_t corners;
};

// What the child's TetGen thread works on (lives on the forking thread's stack, copied into the
// child by fork).
struct ChildJob {
  int fd;
  int stderrFd;  // memfd that receives the child's stderr (assertion messages), or -1
  const TriangleSurface* surface;
  const char* switches;  // nullptr: only test the surface for intersecting facets
};
// Pipe to the parent, for the terminate handler. Written only in a child process after fork,
// so concurrent calls in the parent never share it.
int g_childFd = -1;

bool writeAll(int fd, const void* data, size_t size) {
  const char* p = static_cast<const char*>(data);
  while (size > 0) {
    const ssize_t n = ::write(fd, p, size);
    if (n < 0) {
      if (errno == EINTR) {
        continue;
      }
      return false;
    }
    p += n;
    size -= static_cast<size_t>(n);
  }
  return true;
}

[[noreturn]] void childFinish(Status status, int32_t code) {
  const Header h{status, code, 0, 0, 0, 0};
  writeAll(g_childFd, &h, sizeof(h));
  ::_exit(0);
}

// Reached (without unwinding) when TetGen throws: no frame of the TetGen thread catches.
[[noreturn]] void childTerminateHandler() {
  try {
    std::rethrow_exception(std::current_exception());
  } catch (int code) {
    childFinish(kTetgenError, code);
  } catch (const std::bad_alloc&) {
    childFinish(kOutOfMemory, 0);
  } catch (...) {
    childFinish(kOtherException, 0);
  }
  ::_exit(0);
}

void fillInput(const TriangleSurface& surface, tetgenio& in) {
  in.firstnumber = 0;
  in.numberofpoints = static_cast<int>(surface.points.size());
  in.pointlist = new REAL[3 * surface.points.size()];
  for (size_t i = 0; i < surface.points.size(); ++i) {
    for (int a = 0; a < 3; ++a) {
      in.pointlist[3 * i + a] = surface.points[i][a];
    }
  }
  in.numberoffacets = static_cast<int>(surface.triangles.size());
  in.facetlist = new tetgenio::facet[surface.triangles.size()];
  for (size_t f = 0; f < surface.triangles.size(); ++f) {
    tetgenio::facet& facet = in.facetlist[f];
    tetgenio::init(&facet);
    facet.numberofpolygons = 1;
    facet.polygonlist = new tetgenio::polygon[1];
    tetgenio::init(&facet.polygonlist[0]);
    facet.polygonlist[0].numberofvertices = 3;
    facet.polygonlist[0].vertexlist = new int[3];
    for (int k = 0; k < 3; ++k) {
      facet.polygonlist[0].vertexlist[k] = surface.triangles[f][k];
    }
  }
}

// Body of the child's TetGen thread. Deliberately without try/catch (see the file comment).
void* childTetgenThread(void* arg) {
  const ChildJob& job = *static_cast<const ChildJob*>(arg);
  tetgenio in;
  fillInput(*job.surface, in);
  if (!job.switches) {
    // "d": report intersecting facets (output trifaces) without meshing.
    char detect[] = "pdQ";
    tetgenio found;
    tetrahedralize(detect, &in, &found);
    childFinish(found.numberoftrifaces > 0 ? kSelfIntersecting : kOk, found.numberoftrifaces);
  }
  std::vector<char> switches(job.switches, job.switches + std::strlen(job.switches) + 1);
  tetgenio out;
  tetrahedralize(switches.data(), &in, &out);

  const bool hasRegions =
      out.numberoftetrahedronattributes > 0 && out.tetrahedronattributelist != nullptr;
  const Header h{kOk,
                 0,
                 out.numberofpoints,
                 out.numberoftetrahedra,
                 hasRegions ? 1 : 0,
                 out.numberofcorners >= 4 ? 4 : out.numberofcorners};
  bool ok = writeAll(job.fd, &h, sizeof(h));
  ok = ok &&
       writeAll(job.fd, out.pointlist, sizeof(REAL) * 3 * static_cast<size_t>(out.numberofpoints));
  // The first 4 corners of each tet (the linear tet; more only with second order "o2").
  std::vector<int32_t> tets(static_cast<size_t>(out.numberoftetrahedra) * 4);
  for (size_t t = 0; t < static_cast<size_t>(out.numberoftetrahedra); ++t) {
    for (size_t k = 0; k < 4; ++k) {
      tets[4 * t + k] = out.tetrahedronlist[t * out.numberofcorners + k] - out.firstnumber;
    }
  }
  ok = ok && writeAll(job.fd, tets.data(), sizeof(int32_t) * tets.size());
  if (hasRegions) {
    std::vector<int32_t> regions(static_cast<size_t>(out.numberoftetrahedra));
    for (size_t t = 0; t < regions.size(); ++t) {
      regions[t] =
          static_cast<int32_t>(out.tetrahedronattributelist[t * out.numberoftetrahedronattributes]);
    }
    ok = ok && writeAll(job.fd, regions.data(), sizeof(int32_t) * regions.size());
  }
  ::_exit(ok ? 0 : 1);
}

[[noreturn]] void runChild(ChildJob job) {
  g_childFd = job.fd;
  const int devNull = ::open("/dev/null", O_WRONLY);
  if (devNull >= 0) {
    ::dup2(devNull, STDOUT_FILENO);  // TetGen prints warnings even with "Q"; core never prints
  }
  // Failed assertions in TetGen go to stderr; the parent quotes them in its error message.
  ::dup2(job.stderrFd >= 0 ? job.stderrFd : devNull, STDERR_FILENO);
  std::set_terminate(childTerminateHandler);
  pthread_attr_t attr;
  pthread_attr_init(&attr);
  pthread_attr_setstacksize(&attr, size_t{64} << 20);  // generous: TetGen recursion on large meshes
  pthread_t thread;
  if (pthread_create(&thread, &attr, childTetgenThread, &job) != 0) {
    childFinish(kOtherException, 0);
  }
  pthread_join(thread, nullptr);
  ::_exit(1);  // the thread always _exits; not reached
}

// Last non-empty line the child wrote to stderr (e.g. "...: Assertion `maxz > 0' failed.").
std::string lastStderrLine(int fd) {
  if (fd < 0 || ::lseek(fd, 0, SEEK_SET) != 0) {
    return {};
  }
  std::string text;
  char buffer[4096];
  ssize_t n;
  while ((n = ::read(fd, buffer, sizeof(buffer))) > 0) {
    text.append(buffer, static_cast<size_t>(n));
    if (text.size() > (1 << 16)) {
      text.erase(0, text.size() - 4096);
    }
  }
  while (!text.empty() && (text.back() == '\n' || text.back() == ' ')) {
    text.pop_back();
  }
  const size_t start = text.find_last_of('\n');
  return start == std::string::npos ? text : text.substr(start + 1);
}

std::string signalName(int sig) {
  const char* name = ::strsignal(sig);
  return std::to_string(sig) + (name ? std::string(" (") + name + ")" : std::string());
}

}  // namespace

std::string tetgenErrorMessage(int code) {
  switch (code) {
    case 1:
      return "TetGen ran out of memory (try a larger target edge length)";
    case 2:
      return "TetGen internal error (code 2); the surface may have nearly coincident or degenerate "
             "features";
    case 3:
      return "self-intersecting surface: TetGen found intersecting facets";
    case 4:
      return "TetGen found a very small input feature (code 4): nearly coincident vertices or "
             "extremely thin "
             "triangles on the surface";
    case 5:
      return "TetGen found two very close, nearly overlapping input facets (code 5)";
    case 10:
      return "TetGen rejected the input (code 10: input error)";
    default:
      return "TetGen failed with error code " + std::to_string(code);
  }
}

namespace {

/// A running TetGen child process: its pid, the read end of its pipe and its stderr memfd.
struct Child {
  pid_t pid = -1;
  int fd = -1;
  int stderrFd = -1;
  double startedAt = 0;  // steadySeconds() at the fork
};

double steadySeconds() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

/// Has the child used more than `limit` CPU seconds (0 = no limit)? Its wall time stands in
/// where /proc cannot be read.
bool pastTimeLimit(const Child& child, double limit) {
  if (!(limit > 0)) {
    return false;
  }
  const double cpu = processCpuSeconds(child.pid);
  return (cpu >= 0 ? cpu : steadySeconds() - child.startedAt) > limit;
}

/// Forks a child that meshes `surface` with `switches` (nullptr: tests it for intersecting
/// facets only).
Child startChild(const TriangleSurface& surface, const char* switches) {
  int fds[2];
  if (::pipe2(fds, O_CLOEXEC) != 0) {
    throw GeoLatticeError(std::string("cannot start TetGen: pipe failed: ") + std::strerror(errno));
  }
  const int stderrFd = ::memfd_create("geolattice-tetgen-stderr", MFD_CLOEXEC);  // -1 is tolerated
  const ChildJob job{fds[1], stderrFd, &surface, switches};
  const pid_t pid = ::fork();
  if (pid < 0) {
    const int err = errno;
    ::close(fds[0]);
    ::close(fds[1]);
    if (stderrFd >= 0) {
      ::close(stderrFd);
    }
    throw GeoLatticeError(std::string("cannot start TetGen: fork failed: ") + std::strerror(err));
  }
  if (pid == 0) {
    ::close(fds[0]);
    runChild(job);
  }
  ::close(fds[1]);
  return {pid, fds[0], stderrFd, steadySeconds()};
}

/// Kills a child that is no longer needed and reaps it.
void killChild(Child& child) {
  ::kill(child.pid, SIGKILL);
  int status = 0;
  while (::waitpid(child.pid, &status, 0) < 0 && errno == EINTR) {
  }
  ::close(child.fd);
  if (child.stderrFd >= 0) {
    ::close(child.stderrFd);
  }
}

/// Reads everything the child sends, polling the abort callback, reaps it and returns its
/// message after the header's checks (throws the child's error as a GeoLatticeError).
std::vector<char> finishChild(Child& child, const std::function<bool()>& shouldAbort, Header& h,
                              double cpuSecondsLimit) {
  std::vector<char> data;
  bool aborted = false, timedOut = false;
  std::string readError;
  char buffer[1 << 16];
  while (true) {
    pollfd p{child.fd, POLLIN, 0};
    const int ready = ::poll(&p, 1, 50);
    if (ready < 0 && errno != EINTR) {
      readError = std::string("poll failed: ") + std::strerror(errno);
      break;
    }
    if (shouldAbort && shouldAbort()) {
      aborted = true;
      break;
    }
    if (pastTimeLimit(child, cpuSecondsLimit)) {
      timedOut = true;
      break;
    }
    if (ready <= 0) {
      continue;
    }
    const ssize_t n = ::read(child.fd, buffer, sizeof(buffer));
    if (n < 0) {
      if (errno == EINTR) {
        continue;
      }
      readError = std::string("read failed: ") + std::strerror(errno);
      break;
    }
    if (n == 0) {
      break;  // child closed the pipe (exited)
    }
    data.insert(data.end(), buffer, buffer + n);
  }
  ::close(child.fd);
  if (aborted || timedOut || !readError.empty()) {
    ::kill(child.pid, SIGKILL);
  }
  int status = 0;
  while (::waitpid(child.pid, &status, 0) < 0 && errno == EINTR) {
  }
  const std::string stderrLine = lastStderrLine(child.stderrFd);
  if (child.stderrFd >= 0) {
    ::close(child.stderrFd);
  }
  if (aborted) {
    throw GeoLatticeError("tetrahedralization aborted");
  }
  if (timedOut) {
    throw TetGenTimeLimitExceeded("TetGen did not finish within its time limit (" +
                                  std::to_string(cpuSecondsLimit) + " s of CPU time)");
  }
  if (!readError.empty()) {
    throw GeoLatticeError("lost contact with the TetGen process: " + readError);
  }
  if (data.size() < sizeof(Header)) {
    if (WIFSIGNALED(status)) {
      throw GeoLatticeError(
          "TetGen crashed with signal " + signalName(WTERMSIG(status)) +
          (stderrLine.empty() ? std::string() : " (" + stderrLine + ")") +
          "; the surface may be flat, or have nearly coincident vertices or overlapping facets");
    }
    throw GeoLatticeError("TetGen process ended without a result (exit status " +
                          std::to_string(WIFEXITED(status) ? WEXITSTATUS(status) : -1) + ")");
  }
  std::memcpy(&h, data.data(), sizeof(Header));
  switch (h.status) {
    case kOk:
      break;
    case kTetgenError:
      throw GeoLatticeError(tetgenErrorMessage(h.code));
    case kSelfIntersecting:
      throw GeoLatticeError("self-intersecting surface: TetGen found " + std::to_string(h.code) +
                            " intersecting facets; repair it in its CAD tool" + kWrapHint);
    case kOutOfMemory:
      throw GeoLatticeError(tetgenErrorMessage(1));
    default:
      throw GeoLatticeError("TetGen failed with an unexpected exception");
  }
  return data;
}

}  // namespace

double processCpuSeconds(int pid) {
  std::ifstream in("/proc/" + std::to_string(pid) + "/stat");
  const std::string stat((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  // Fields after the command name, which is in parentheses and may hold spaces: state (3rd
  // field) ... utime (14th) stime (15th), in clock ticks.
  const size_t close = stat.rfind(')');
  if (close == std::string::npos) {
    return -1.0;
  }
  std::istringstream fields(stat.substr(close + 1));
  std::string field;
  for (int i = 3; i < 14 && fields >> field; ++i) {
  }
  long long utime = -1, stime = -1;
  if (!(fields >> utime >> stime) || utime < 0 || stime < 0) {
    return -1.0;
  }
  const long ticks = ::sysconf(_SC_CLK_TCK);
  return ticks > 0 ? static_cast<double>(utime + stime) / static_cast<double>(ticks) : -1.0;
}

TetGenRun::TetGenRun(const TriangleSurface& surface, const std::string& switches) {
  if (switches.find('p') == std::string::npos) {
    throw GeoLatticeError("runTetGen: switches \"" + switches + "\" lack 'p' (mesh a surface)");
  }
  const Child child = startChild(surface, switches.c_str());
  pid_ = child.pid;
  fd_ = child.fd;
  stderrFd_ = child.stderrFd;
  startedAt_ = child.startedAt;
}

TetGenRun::~TetGenRun() {
  if (pid_ >= 0) {
    Child child{pid_, fd_, stderrFd_, startedAt_};
    killChild(child);
  }
}

TetGenOutput TetGenRun::finish(const std::function<bool()>& shouldAbort, double cpuSecondsLimit) {
  if (pid_ < 0) {
    throw GeoLatticeError("TetGen run read twice");
  }
  Child child{pid_, fd_, stderrFd_, startedAt_};
  pid_ = -1;  // finishChild reaps it and closes its descriptors, also when it throws
  Header h{};
  const std::vector<char> data = finishChild(child, shouldAbort, h, cpuSecondsLimit);
  if (h.corners != 4 || h.pointCount < 0 || h.tetCount < 0) {
    throw GeoLatticeError("TetGen produced an unexpected mesh (" + std::to_string(h.corners) +
                          " corners per tet)");
  }
  const size_t pointBytes = sizeof(double) * 3 * static_cast<size_t>(h.pointCount);
  const size_t tetBytes = sizeof(int32_t) * 4 * static_cast<size_t>(h.tetCount);
  const size_t regionBytes = h.hasRegions ? sizeof(int32_t) * static_cast<size_t>(h.tetCount) : 0;
  if (data.size() != sizeof(Header) + pointBytes + tetBytes + regionBytes) {
    throw GeoLatticeError("TetGen process sent an incomplete mesh (" + std::to_string(data.size()) +
                          " bytes)");
  }
  TetGenOutput output;
  const char* p = data.data() + sizeof(Header);
  output.mesh.points.resize(static_cast<size_t>(h.pointCount));
  for (auto& point : output.mesh.points) {
    std::memcpy(point.data(), p, 3 * sizeof(double));
    p += 3 * sizeof(double);
  }
  output.mesh.tets.resize(static_cast<size_t>(h.tetCount));
  for (auto& tet : output.mesh.tets) {
    int32_t v[4];
    std::memcpy(v, p, sizeof(v));
    p += sizeof(v);
    tet = {v[0], v[1], v[2], v[3]};
  }
  if (h.hasRegions) {
    output.regions.resize(static_cast<size_t>(h.tetCount));
    std::memcpy(output.regions.data(), p, regionBytes);
  }
  return output;
}

void testForIntersectingFacets(const TriangleSurface& surface,
                               const std::function<bool()>& shouldAbort, double cpuSecondsLimit) {
  Child tester = startChild(surface, nullptr);
  Header verdict{};
  finishChild(tester, shouldAbort, verdict, cpuSecondsLimit);
}

TetGenOutput runTetGen(const TriangleSurface& surface, const std::string& switches,
                       const std::function<bool()>& shouldAbort, IntersectionTest test,
                       double cpuSecondsLimit) {
  TetGenRun mesher(surface, switches);
  if (test == IntersectionTest::Run) {
    // The test in a second child beside the meshing one (on another core): its verdict comes
    // first, as if it had run before the meshing, but costs no time of its own. A failure
    // kills the mesher (its destructor).
    testForIntersectingFacets(surface, shouldAbort, cpuSecondsLimit);
  }
  return mesher.finish(shouldAbort, cpuSecondsLimit);
}

}  // namespace geolattice
