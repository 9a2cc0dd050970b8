// SPDX-License-Identifier: BSD-2-Clause
#include "files.h"
#include <climits>
#include <cstdlib>
#include <sys/stat.h>
#include <unistd.h>
#include <cerrno>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <fcntl.h>
#include <fstream>

namespace fsi {

PetscErrorCode CheckOnRankZero(MPI_Comm comm, PetscErrorCode code, const std::function<std::string()> &check)
{
  PetscMPIInt rank;
  std::string sentence;
  int         len = 0;

  PetscFunctionBegin;
  PetscCallMPI(MPI_Comm_rank(comm, &rank));
  if (!rank) sentence = check(), len = (int)sentence.size();
  PetscCallMPI(MPI_Bcast(&len, 1, MPI_INT, 0, comm));
  if (!len) PetscFunctionReturn(0);
  sentence.resize(len);
  PetscCallMPI(MPI_Bcast(&sentence[0], len, MPI_CHAR, 0, comm));
  SETERRQ(comm, code, "%s", sentence.c_str());
}

PetscErrorCode CheckOnAnyRank(MPI_Comm comm, PetscErrorCode code, const std::string &sentence)
{
  PetscMPIInt rank, first, mine;

  PetscFunctionBegin;
  PetscCallMPI(MPI_Comm_rank(comm, &rank));
  mine = sentence.empty() ? PETSC_MPI_INT_MAX : rank;
  PetscCallMPI(MPI_Allreduce(&mine, &first, 1, MPI_INT, MPI_MIN, comm));
  if (first == PETSC_MPI_INT_MAX) PetscFunctionReturn(0);
  int         len = (int)sentence.size();
  std::string s   = sentence;
  PetscCallMPI(MPI_Bcast(&len, 1, MPI_INT, first, comm));
  s.resize(len);
  PetscCallMPI(MPI_Bcast(&s[0], len, MPI_CHAR, first, comm));
  SETERRQ(comm, code, "%s", s.c_str());
}

/* Why `path` cannot be written, or "" if it can. */
static std::string Unwritable(const std::string &path, bool regular)
{
  const size_t      slash = path.find_last_of('/');
  const std::string dir   = slash == std::string::npos ? "." : slash == 0 ? "/" : path.substr(0, slash);
  struct stat       st;

  if (path.empty() || path.back() == '/') return "name a file, not a directory";
  if (stat(dir.c_str(), &st) != 0) return "the directory " + dir + " does not exist";
  if (!S_ISDIR(st.st_mode)) return dir + " is not a directory";
  if (access(dir.c_str(), W_OK | X_OK) != 0) return "the directory " + dir + " is not writable";
  if (stat(path.c_str(), &st) == 0 && S_ISDIR(st.st_mode)) return "it is a directory";
  if (regular && stat(path.c_str(), &st) == 0 && !S_ISREG(st.st_mode)) return "it is not a regular file but a device, FIFO or socket, which the run would replace";
  if (access(path.c_str(), F_OK) == 0 && access(path.c_str(), W_OK) != 0) return "the file is not writable";
  return "";
}

PetscErrorCode CheckWritable(MPI_Comm comm, const char *option, const std::string &path, bool regular)
{
  PetscFunctionBegin;
  PetscCall(CheckOnRankZero(comm, PETSC_ERR_FILE_OPEN, [&]() {
    const std::string why = Unwritable(path, regular);
    return why.empty() ? why : std::string(option) + " " + path + ": the run cannot write this file (" + why + ")";
  }));
  PetscFunctionReturn(0);
}

std::string OpenInput(const char *option, const std::string &path, std::ifstream &in)
{
  struct stat st;
  if (stat(path.c_str(), &st) != 0) return std::string(option) + " " + path + ": no such file";
  if (!S_ISREG(st.st_mode)) return std::string(option) + " " + path + ": not a regular file";
  in.open(path);
  return in ? "" : std::string(option) + " " + path + ": cannot be read";
}

PetscErrorCode FileSize(MPI_Comm comm, const std::string &path, long long *bytes)
{
  PetscMPIInt rank;

  PetscFunctionBegin;
  PetscCallMPI(MPI_Comm_rank(comm, &rank));
  if (!rank) {
    std::ifstream in(path, std::ios::binary | std::ios::ate);
    *bytes = in ? (long long)in.tellg() : -1;
  }
  PetscCallMPI(MPI_Bcast(bytes, 1, MPI_LONG_LONG, 0, comm));
  PetscFunctionReturn(0);
}

PetscErrorCode FileDigest(MPI_Comm comm, const std::string &path, std::string *digest)
{
  PetscMPIInt        rank;
  unsigned long long h = FnvStart;

  PetscFunctionBegin;
  PetscCallMPI(MPI_Comm_rank(comm, &rank));
  if (!rank) {
    std::ifstream in(path, std::ios::binary);
    char          buf[1 << 16];
    while (in.read(buf, sizeof(buf)) || in.gcount() > 0) h = Fnv1a(buf, (size_t)in.gcount(), h);
  }
  PetscCallMPI(MPI_Bcast(&h, 1, MPI_UNSIGNED_LONG_LONG, 0, comm));
  char hex[17];
  std::snprintf(hex, sizeof(hex), "%016llx", h);
  *digest = hex;
  PetscFunctionReturn(0);
}

/* "" if no live run holds `path`'s lock (a lock whose process has ended is removed), else who. */
static std::string Holder(const std::string &path)
{
  const std::string lock = path + ".lock";
  char              host[256] = "";
  gethostname(host, sizeof(host) - 1);
  std::ifstream in(lock);
  if (!in) return "";
  std::string theirHost;
  long        pid = 0;
  in >> theirHost >> pid;
  if (theirHost != host) return "a run on host " + theirHost + " (process " + std::to_string(pid) + ") is writing it; if that run has ended, remove " + lock;
  if (pid > 0 && (kill((pid_t)pid, 0) == 0 || errno == EPERM)) return "another run (process " + std::to_string(pid) + ") is writing it; give another name, or wait until that run ends (or remove " + lock + " if no run is)";
  std::remove(lock.c_str()); /* its run ended without removing it */
  return "";
}

/* "" if this process may write `path`, else who holds it. */
static std::string Claim(const std::string &path)
{
  const std::string lock = path + ".lock";
  char              host[256] = "";
  gethostname(host, sizeof(host) - 1);
  for (int attempt = 0; attempt < 2; attempt++) {
    const int fd = open(lock.c_str(), O_WRONLY | O_CREAT | O_EXCL, 0644);
    if (fd >= 0) {
      const std::string me = std::string(host) + " " + std::to_string((long)getpid()) + "\n";
      const bool        ok = write(fd, me.c_str(), me.size()) == (ssize_t)me.size();
      close(fd);
      return ok ? "" : "cannot write its lock file " + lock;
    }
    if (errno != EEXIST) return "cannot create its lock file " + lock + " (" + std::strerror(errno) + ")";
    const std::string who = Holder(path);
    if (!who.empty()) return who;
  }
  return "cannot take over its lock file " + lock;
}

PetscErrorCode ClaimFile(MPI_Comm comm, const char *option, const std::string &path)
{
  PetscFunctionBegin;
  PetscCall(CheckOnRankZero(comm, PETSC_ERR_FILE_OPEN, [&]() {
    const std::string why = Claim(path);
    return why.empty() ? why : std::string(option) + " " + path + ": " + why;
  }));
  PetscFunctionReturn(0);
}

PetscErrorCode CheckNotClaimed(MPI_Comm comm, const char *option, const std::string &path)
{
  PetscFunctionBegin;
  PetscCall(CheckOnRankZero(comm, PETSC_ERR_FILE_OPEN, [&]() {
    const std::string who = Holder(path);
    return who.empty() ? who : std::string(option) + " " + path + ": " + who + "; reading it now would take that run's later steps";
  }));
  PetscFunctionReturn(0);
}

std::string CanonicalPath(const std::string &path)
{
  char        full[PATH_MAX];
  const size_t slash = path.rfind('/');
  const std::string dir = slash == std::string::npos ? "." : slash == 0 ? "/" : path.substr(0, slash), base = slash == std::string::npos ? path : path.substr(slash + 1);
  if (realpath(path.c_str(), full)) return full; /* the file exists: its links resolved */
  if (realpath(dir.c_str(), full)) return std::string(full) + "/" + base;
  return path;
}

PetscErrorCode ReleaseFile(MPI_Comm comm, const std::string &path)
{
  PetscMPIInt rank;

  PetscFunctionBegin;
  PetscCallMPI(MPI_Comm_rank(comm, &rank));
  if (!rank) std::remove((path + ".lock").c_str());
  PetscFunctionReturn(0);
}

PetscErrorCode CloseWritten(MPI_Comm comm, const char *option, const char *path, FILE *fp)
{
  PetscFunctionBegin;
  PetscCall(CheckOnRankZero(comm, PETSC_ERR_FILE_WRITE, [&]() {
    errno   = 0;
    bool ok = fflush(fp) == 0 && !ferror(fp);
    if (!ok && !errno) { /* PetscFPrintf() flushes every line and drops the error: one more byte tells why */
      clearerr(fp);
      fputc('\n', fp);
      fflush(fp);
    }
    const int e = errno;
    ok          = fclose(fp) == 0 && ok;
    if (ok) return std::string();
    return std::string(option) + " " + path + ": writing it failed (" + std::strerror(e ? e : errno) + "); the file is incomplete";
  }));
  PetscFunctionReturn(0);
}

} // namespace fsi
