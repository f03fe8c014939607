#include "cad/detail/ChildProcess.h"

#include <BRep_Builder.hxx>
#include <BinTools.hxx>
#include <Standard_Failure.hxx>
#include <TopoDS_Compound.hxx>
#include <TopoDS_Iterator.hxx>

#include <fcntl.h>
#include <poll.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <csignal>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "mesher/core/Cancel.h"
#include "mesher/core/Error.h"
#include "mesher/core/Log.h"

namespace aniso::cad::detail {
namespace {

namespace fs = std::filesystem;

void putInt(std::ostream& out, std::int64_t v) { out.write(reinterpret_cast<const char*>(&v), sizeof v); }
void putString(std::ostream& out, const std::string& s) {
  putInt(out, static_cast<std::int64_t>(s.size()));
  out.write(s.data(), static_cast<std::streamsize>(s.size()));
}
std::int64_t getInt(std::istream& in) {
  std::int64_t v = 0;
  if (!in.read(reinterpret_cast<char*>(&v), sizeof v)) throw MeshingError("child process result is truncated");
  return v;
}
std::string getString(std::istream& in) {
  const std::int64_t n = getInt(in);
  if (n < 0 || n > (std::int64_t{1} << 32)) throw MeshingError("child process result is corrupt");
  std::string s(static_cast<size_t>(n), '\0');
  if (!in.read(s.data(), n)) throw MeshingError("child process result is truncated");
  return s;
}

/// The files of one exchange: the outcome and names (meta), the shape (binary BREP).
struct Exchange {
  fs::path dir;
  fs::path meta() const { return dir / "meta.bin"; }
  fs::path shape() const { return dir / "shape.bin"; }
};

/// Writes impl's shape and, after it in one compound, the key solid of every part name and
/// the key face of every face tag (the same TShapes: BREP keeps the sharing, so the keys
/// find their solids and faces on reading).
void writeShape(const CadModel::Impl& impl, const Exchange& x, std::ostream& meta) {
  BRep_Builder b;
  TopoDS_Compound all;
  b.MakeCompound(all);
  putInt(meta, impl.shape.IsNull() ? 0 : 1);
  if (!impl.shape.IsNull()) b.Add(all, impl.shape);
  putInt(meta, impl.solidsLost);
  putInt(meta, impl.facesInFile);
  putString(meta, impl.fileUnit);
  putInt(meta, static_cast<std::int64_t>(impl.names.size()));
  for (size_t i = 0; i < impl.names.size(); ++i) {
    putString(meta, impl.names[i]);
    putString(meta, i < impl.partColors.size() ? impl.partColors[i] : std::string());
  }
  putInt(meta, static_cast<std::int64_t>(impl.faceTags.size()));
  for (const FaceTag& t : impl.faceTags) {
    putString(meta, t.name);
    putString(meta, t.color);
  }
  for (const TopTools_DataMapOfShapeInteger* index : {&impl.nameIndex, &impl.faceTagIndex}) {
    putInt(meta, index->Extent());
    for (TopTools_DataMapIteratorOfDataMapOfShapeInteger it(*index); it.More(); it.Next()) {
      b.Add(all, it.Key());
      putInt(meta, it.Value());
    }
  }
  std::ofstream out(x.shape(), std::ios::binary);
  BinTools::Write(all, out);
  if (!out.flush()) throw MeshingError("cannot write the child process's shape");
}

void readShape(CadModel::Impl& impl, const Exchange& x, std::istream& meta) {
  const bool hasShape = getInt(meta) != 0;
  const int solidsLost = static_cast<int>(getInt(meta));
  const int facesInFile = static_cast<int>(getInt(meta));
  std::string fileUnit = getString(meta);
  std::vector<std::string> names(static_cast<size_t>(getInt(meta))), colors(names.size());
  for (size_t i = 0; i < names.size(); ++i) {
    names[i] = getString(meta);
    colors[i] = getString(meta);
  }
  std::vector<FaceTag> tags(static_cast<size_t>(getInt(meta)));
  for (FaceTag& t : tags) {
    t.name = getString(meta);
    t.color = getString(meta);
  }
  std::vector<int> keyName(static_cast<size_t>(getInt(meta)));
  for (int& k : keyName) k = static_cast<int>(getInt(meta));
  std::vector<int> keyTag(static_cast<size_t>(getInt(meta)));
  for (int& k : keyTag) k = static_cast<int>(getInt(meta));
  TopoDS_Shape all;
  std::ifstream in(x.shape(), std::ios::binary);
  BinTools::Read(all, in);
  if (all.IsNull()) throw MeshingError("cannot read the child process's shape");
  TopoDS_Iterator it(all, /*cumOri*/ false, /*cumLoc*/ false);
  impl.shape = TopoDS_Shape();
  if (hasShape) {
    impl.shape = it.Value();
    it.Next();
  }
  impl.solidsLost = solidsLost;
  impl.facesInFile = facesInFile;
  impl.fileUnit = std::move(fileUnit);
  impl.names = std::move(names);
  impl.partColors = std::move(colors);
  impl.faceTags = std::move(tags);
  const auto bind = [&it](TopTools_DataMapOfShapeInteger& index, const std::vector<int>& values) {
    index.Clear();
    for (const int k : values) {
      if (!it.More()) throw MeshingError("child process result is corrupt");
      index.Bind(it.Value(), k);
      it.Next();
    }
  };
  bind(impl.nameIndex, keyName);
  bind(impl.faceTagIndex, keyTag);
}

/// Runs body, every exception an outcome (InputError: Input, anything else: Failed).
ChildOutcome guarded(const std::function<std::string()>& body) {
  try {
    return {ChildOutcome::Done, {}, body()};
  } catch (const InputError& e) {
    return {ChildOutcome::Input, e.what(), {}};
  } catch (const Standard_Failure& e) {
    return {ChildOutcome::Failed, std::string(e.DynamicType()->Name()) + ": " + e.GetMessageString(), {}};
  } catch (const std::exception& e) {
    return {ChildOutcome::Failed, e.what(), {}};
  } catch (...) {
    return {ChildOutcome::Failed, "unknown error", {}};
  }
}

[[noreturn]] void childMain(CadModel::Impl& impl, const std::function<std::string(CadModel::Impl&)>& work,
                            const Exchange& x) {
  // whatever OCCT prints while dying ("*** Abort ***") is not the program's output
  const int devNull = open("/dev/null", O_WRONLY);
  if (devNull >= 0) {
    dup2(devNull, STDOUT_FILENO);
    dup2(devNull, STDERR_FILENO);
  }
  std::ofstream meta(x.meta(), std::ios::binary);
  std::ostringstream shapeMeta;
  const TopoDS_Shape before = impl.shape;
  const int namedBefore = impl.nameIndex.Extent(), taggedBefore = impl.faceTagIndex.Extent();
  const ChildOutcome o = guarded([&] {
    std::string payload = work(impl);
    // an unchanged shape is not sent back (the parent's copy is the same)
    const bool unchanged = !before.IsNull() && impl.shape.IsEqual(before) && impl.nameIndex.Extent() == namedBefore &&
                           impl.faceTagIndex.Extent() == taggedBefore;
    putInt(shapeMeta, unchanged ? 0 : 1);
    if (!unchanged) writeShape(impl, x, shapeMeta);
    return payload;
  });
  putInt(meta, o.kind);
  putString(meta, o.message);
  putString(meta, o.payload);
  if (o.kind == ChildOutcome::Done) meta << shapeMeta.str();
  meta.flush();
  _exit(meta ? 0 : 1);  // no atexit handlers, no flushing of the parent's buffers
}

/// Waits until the child has ended (its end of `alive` closes) or the token stops the
/// run: then the child is killed and Cancelled thrown naming `phase`. A deadline that passed
/// while the child ran is this phase's too, even when the child ended before it was seen.
void awaitChild(pid_t pid, int alive, const CancelToken* cancel, const char* phase) {
  constexpr int kPollMs = 50;  // how often a request without deadline is noticed
  pollfd p{alive, POLLIN, 0};
  while (cancel) {  // bounded by the token's deadline
    const int r = poll(&p, 1, kPollMs);
    const bool ended = r > 0 || (r < 0 && errno != EINTR);
    if (ended && !cancel->stopped()) return;
    if (cancel->stopped()) {
      kill(pid, SIGKILL);
      waitpid(pid, nullptr, 0);
      cancel->check(phase);
    }
  }
}

/// The parent's side: the child's status and files.
ChildOutcome collect(pid_t pid, CadModel::Impl& impl, const Exchange& x) {
  int status = 0;
  while (waitpid(pid, &status, 0) < 0)
    if (errno != EINTR) return {ChildOutcome::Failed, std::string("waitpid: ") + std::strerror(errno), {}};
  if (WIFSIGNALED(status)) {
    const int sig = WTERMSIG(status);
    return {ChildOutcome::Crashed, "signal " + std::to_string(sig) + " (" + strsignal(sig) + ")", {}};
  }
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0)
    return {ChildOutcome::Failed, "the child process exited with status " + std::to_string(WEXITSTATUS(status)), {}};
  try {
    std::ifstream meta(x.meta(), std::ios::binary);
    ChildOutcome o;
    o.kind = static_cast<ChildOutcome::Kind>(getInt(meta));
    o.message = getString(meta);
    o.payload = getString(meta);
    if (o.kind == ChildOutcome::Done && getInt(meta) != 0) readShape(impl, x, meta);
    return o;
  } catch (const Standard_Failure& e) {
    return {ChildOutcome::Failed, e.GetMessageString(), {}};
  } catch (const std::exception& e) {
    return {ChildOutcome::Failed, e.what(), {}};
  }
}

}  // namespace

ChildOutcome runInChild(CadModel::Impl& impl, const char* phase,
                        const std::function<std::string(CadModel::Impl&)>& work) {
  std::string pattern = (fs::temp_directory_path() / "anisomesh-XXXXXX").string();
  if (!mkdtemp(pattern.data()))
    throw MeshingError(std::string("cannot create a temporary folder: ") + std::strerror(errno));
  const Exchange x{pattern};
  std::fflush(nullptr);  // nothing buffered is written twice
  int alive[2] = {-1, -1};  // the child holds the write end until it ends
  pid_t pid = -1;
  if (testCrashRequested("fork-fails")) errno = EAGAIN;  // test hook: no process to spare
  else if (pipe(alive) == 0) pid = fork();
  std::error_code ec;
  if (pid < 0) {  // no process to spare (memory, limits): the work runs here, unprotected
    const int err = errno;
    for (const int fd : alive)
      if (fd >= 0) close(fd);
    logWarning(std::string("cannot start a child process (") + std::strerror(err) + "): " + phase +
               " runs without protection from a crash of OpenCASCADE");
    fs::remove_all(x.dir, ec);
    const CadModel::Impl saved = impl;
    ChildOutcome o = guarded([&] { return work(impl); });
    if (!o.ok()) impl = saved;
    return o;
  }
  if (pid == 0) {
    close(alive[0]);
    childMain(impl, work, x);
  }
  close(alive[1]);
  ChildOutcome o;
  try {
    awaitChild(pid, alive[0], impl.cancel, phase);
    o = collect(pid, impl, x);
  } catch (...) {
    close(alive[0]);
    fs::remove_all(x.dir, ec);
    throw;
  }
  close(alive[0]);
  fs::remove_all(x.dir, ec);
  return o;
}

bool testCrashRequested(const char* point) {
  const char* env = std::getenv("ANISOMESH_TEST_CRASH");
  if (!env) return false;
  std::stringstream list(env);
  std::string item;
  while (std::getline(list, item, ','))
    if (item == point) return true;
  return false;
}

void testCrashPoint(const char* point) {
  if (testCrashRequested(point)) std::raise(SIGSEGV);
}

}  // namespace aniso::cad::detail
