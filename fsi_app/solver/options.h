// SPDX-License-Identifier: BSD-2-Clause
/* Reading a block's or the scene's options: every number checked where it is read (finite, in
   its range), every choice against its list, and the options that define the problem recorded
   with their values, which a checkpoint keeps and a restart compares. */
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
  /* points x1,y1,z1,x2,... (at most 20) */
  PetscErrorCode Points(const char *name, const char *text, std::vector<PetscReal> &xyz) const;
  /* A value that is not one of the n names of list stops the run with one message: PETSc's own
     parsers raise it on every rank. */
  PetscErrorCode CheckChoice(const char *name, const char *const *list, PetscInt n) const;
  template <class E>
  PetscErrorCode Enum(const char *name, const char *text, const char *const *list, E *v, OptionRole role) const
  {
    PetscInt n = 0;

    PetscFunctionBegin;
    while (list[n + 2]) n++; /* PETSc's enum lists end with the type name, the prefix and a null */
    PetscCall(CheckChoice(name, list, n));
    PetscCall(PetscOptionsEnum(name, text, nullptr, list, (PetscEnum)*v, (PetscEnum *)v, nullptr));
    Record(name, role, list[*v]);
    PetscFunctionReturn(0);
  }
  /* An option's old name: its value moves to the new name, and the run says the new name once. */
  PetscErrorCode Renamed(const char *old, const char *name) const;

  void Record(const char *name, OptionRole role, const std::string &value) const;
  void Record(const char *name, OptionRole role, const PetscReal *v, PetscInt n) const;
};

} // namespace fsi
