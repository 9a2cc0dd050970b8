// SPDX-License-Identifier: BSD-2-Clause
/* Reading a block's or the scene's options: every number checked where it is read (given a
   value, finite, in its range, an integer that fits), every choice against its list, and the
   options that define the problem recorded with their values, which a checkpoint keeps and a
   restart compares. -help prints one line per option with its value, its default when the
   scene changed it, and its range; every name read is known, so that an unused option that
   looks like one of them is refused (CheckUnusedOptions). */
#pragma once

#include <petscsys.h>
#include <limits>
#include <map>
#include <string>
#include <vector>

namespace fsi {

/* v as C's %g writes it (PETSc's %g writes 1 and nan as "1." and "nan."). */
std::string Number(PetscReal v);

/* The interval a number read from an option must lie in, each end open or closed: the
   physics' bounds (a density is positive, a ramp's length >= 0); any real number if unbounded. */
struct Range {
  PetscReal lo = -std::numeric_limits<PetscReal>::infinity(), hi = std::numeric_limits<PetscReal>::infinity();
  PetscBool openLo = PETSC_FALSE, openHi = PETSC_FALSE;

  PetscBool   Contains(PetscReal v) const { return (PetscBool)((openLo ? v > lo : v >= lo) && (openHi ? v < hi : v <= hi)); }
  std::string Text() const;
};
extern const Range Any, Positive, NonNegative;
inline Range       AtLeast(PetscReal lo) { return {lo}; }

enum OptionRole { RUN, PROBLEM }; /* PROBLEM: defines the equations, their unknowns, conditions and loads */

/* The options between PetscOptionsBegin() and PetscOptionsEnd(); `problem` collects the
   PROBLEM options' values. */
struct OptionReader {
  PetscOptionItems                   *PetscOptionsObject; /* the name PETSc's PetscOptions*() macros use */
  std::map<std::string, std::string> &problem;

  PetscErrorCode Check(const char *name, const PetscReal *v, PetscInt n, const Range &r) const;
  PetscErrorCode Real(const char *name, const char *text, PetscReal *v, const Range &r, OptionRole role) const;
  /* up to *n values; *n is how many were given */
  PetscErrorCode Reals(const char *name, const char *text, PetscReal *v, PetscInt *n, PetscBool *set, const Range &r, OptionRole role) const;
  PetscErrorCode Int(const char *name, const char *text, PetscInt *v, const Range &r, OptionRole role) const;
  PetscErrorCode String(const char *name, const char *text, char *v, size_t len, OptionRole role) const;
  PetscErrorCode Bool(const char *name, const char *text, PetscBool *v, OptionRole role) const;
  /* a list of at most `max` numbers, none by default */
  PetscErrorCode Numbers(const char *name, const char *text, std::vector<PetscReal> &v, PetscInt max, const char *what, OptionRole role) const;
  /* points x1,y1,z1,x2,... (at most 20) */
  PetscErrorCode Points(const char *name, const char *text, std::vector<PetscReal> &xyz) const;
  /* a choice of a PETSc enum list (names, then the type name, the prefix and a null); a value
     not in the list stops the run with one message (PETSc's own parser raises it on every rank) */
  PetscErrorCode Choice(const char *name, const char *text, const char *const *list, PetscInt *v, OptionRole role) const;
  template <class E>
  PetscErrorCode Enum(const char *name, const char *text, const char *const *list, E *v, OptionRole role) const
  {
    PetscInt c = (PetscInt)*v;

    PetscFunctionBegin;
    PetscCall(Choice(name, text, list, &c, role));
    *v = (E)c;
    PetscFunctionReturn(0);
  }
  /* An option's old name: its value moves to the new name, and the run says the new name once. */
  PetscErrorCode Renamed(const char *old, const char *name) const;

  void Record(const char *name, OptionRole role, const std::string &value) const;
  void Record(const char *name, OptionRole role, const PetscReal *v, PetscInt n) const;

private:
  /* The option's value as given; *given if it is in the database. `what` says what a value
     must be, for the error of an option given without one. */
  PetscErrorCode Given(const char *name, const char *what, std::string &value, PetscBool *given) const;
  /* -help: "  -name <value>: text (range; default d)" */
  PetscErrorCode Help(const char *name, const std::string &value, const std::string &def, const char *text, const std::string &range) const;
};

/* Every option that a reader has read, for CheckUnusedOptions. */
void KnownOption(const char *name);

/* Options left unused in the database that start with one of `prefixes` ("structure_") or are
   within a letter or two of a known option stop the run, naming the closest known option
   ("-structure_presure: no such option; did you mean -structure_pressure?"): a misspelled
   option would otherwise leave its default in force without a word. */
PetscErrorCode CheckUnusedOptions(MPI_Comm comm, const std::vector<std::string> &prefixes);

} // namespace fsi
