// SPDX-License-Identifier: BSD-2-Clause
#include "files.h"
#include <sys/stat.h>
#include <unistd.h>
#include <cstdio>
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

/* Why `path` cannot be written, or "" if it can. */
static std::string Unwritable(const std::string &path)
{
  const size_t      slash = path.find_last_of('/');
  const std::string dir   = slash == std::string::npos ? "." : slash == 0 ? "/" : path.substr(0, slash);
  struct stat       st;

  if (path.empty() || path.back() == '/') return "name a file, not a directory";
  if (stat(dir.c_str(), &st) != 0) return "the directory " + dir + " does not exist";
  if (!S_ISDIR(st.st_mode)) return dir + " is not a directory";
  if (access(dir.c_str(), W_OK | X_OK) != 0) return "the directory " + dir + " is not writable";
  if (stat(path.c_str(), &st) == 0 && S_ISDIR(st.st_mode)) return "it is a directory";
  if (access(path.c_str(), F_OK) == 0 && access(path.c_str(), W_OK) != 0) return "the file is not writable";
  return "";
}

PetscErrorCode CheckWritable(MPI_Comm comm, const char *option, const std::string &path)
{
  PetscFunctionBegin;
  PetscCall(CheckOnRankZero(comm, PETSC_ERR_FILE_OPEN, [&]() {
    const std::string why = Unwritable(path);
    return why.empty() ? why : std::string(option) + " " + path + ": the run cannot write this file (" + why + ")";
  }));
  PetscFunctionReturn(0);
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

} // namespace fsi
