// SPDX-License-Identifier: BSD-2-Clause
/* The files a run reads and writes, checked on rank 0 (where PETSc reads and writes them)
   before it uses them, so that a bad path or a damaged file is one sentence on every rank
   that names the option and the file, not a library's error halfway through the run. */
#pragma once

#include <petscsys.h>
#include <cstdio>
#include <functional>
#include <fstream>
#include <string>

namespace fsi {

/* Run `check` on rank 0 of comm; a nonempty sentence it returns is the error (code `code`)
   of every rank. */
PetscErrorCode CheckOnRankZero(MPI_Comm comm, PetscErrorCode code, const std::function<std::string()> &check);
/* The same for a check every rank makes on its own part (`sentence`: "" if it passed): the
   first rank's sentence stops every rank, printed once. */
PetscErrorCode CheckOnAnyRank(MPI_Comm comm, PetscErrorCode code, const std::string &sentence);

/* The run can write `path` (the value of `option`): its directory exists and takes new files,
   and the file, if it is there, is a writable file, and a regular one when `regular` (a file the
   run replaces by renaming, or HDF5's: a device node or FIFO would be replaced or misused). */
PetscErrorCode CheckWritable(MPI_Comm comm, const char *option, const std::string &path, bool regular = true);

/* Claim `path` for this run: rank 0 creates `path`.lock holding its host and process id, and
   refuses (a sentence naming `option`) while another live run holds it; a lock whose process
   has ended is taken over. ReleaseFile removes it. */
PetscErrorCode ClaimFile(MPI_Comm comm, const char *option, const std::string &path);
PetscErrorCode ReleaseFile(MPI_Comm comm, const std::string &path);
/* Refuse to read `path` (the value of `option`) while another live run holds its lock: it is
   writing the file. */
PetscErrorCode CheckNotClaimed(MPI_Comm comm, const char *option, const std::string &path);
/* The absolute path of `path` with its links resolved (of its folder, if the file is not there
   yet): two names of one file give one path. */
std::string CanonicalPath(const std::string &path);

/* Close a file opened on rank 0 for writing, and stop with a sentence naming `option` and the
   system's reason if anything written to it was lost (a full disk: /dev/full). */
PetscErrorCode CloseWritten(MPI_Comm comm, const char *option, const char *path, FILE *fp);

/* Open the text file `path` (the value of `option`) for reading on this rank: "" or the
   sentence saying why not (no such file, not a regular file, unreadable). */
std::string OpenInput(const char *option, const std::string &path, std::ifstream &in);

/* The size of `path` in bytes as rank 0 sees it; -1 if it cannot be opened. */
PetscErrorCode FileSize(MPI_Comm comm, const std::string &path, long long *bytes);

/* 64-bit FNV-1a of n bytes, continuing from h (start: FnvStart). */
inline const unsigned long long FnvStart = 14695981039346656037ull;
inline unsigned long long Fnv1a(const void *bytes, size_t n, unsigned long long h)
{
  for (size_t i = 0; i < n; i++) h = (h ^ ((const unsigned char *)bytes)[i]) * 1099511628211ull;
  return h;
}

/* A digest of the bytes of `path` as rank 0 reads them (64-bit FNV-1a, in hex), on every rank:
   what a checkpoint records of its mesh file. */
PetscErrorCode FileDigest(MPI_Comm comm, const std::string &path, std::string *digest);

} // namespace fsi
