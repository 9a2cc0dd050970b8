// SPDX-License-Identifier: BSD-2-Clause
#include "solver/options.h"
#include <cstdio>

namespace fsi {

std::string Number(PetscReal v)
{
  char s[32];
  std::snprintf(s, sizeof(s), "%g", (double)v);
  return s;
}

std::string Range::Text() const
{
  if (lo == 0 && openLo && PetscIsInfReal(hi)) return "positive";
  if (PetscIsInfReal(hi)) return std::string(openLo ? "> " : ">= ") + Number(lo);
  return std::string("in ") + (openLo ? "(" : "[") + Number(lo) + ", " + Number(hi) + (openHi ? ")" : "]");
}

const Range Any{}, Positive = {0, std::numeric_limits<PetscReal>::infinity(), PETSC_TRUE}, NonNegative = {0};

PetscErrorCode OptionReader::Check(const char *name, const PetscReal *v, PetscInt n, const Range &r) const
{
  PetscFunctionBegin;
  for (PetscInt i = 0; i < n; i++) {
    char which[32] = "value";
    if (n > 1) PetscCall(PetscSNPrintf(which, sizeof(which), "value %" PetscInt_FMT, i + 1));
    PetscCheck(!PetscIsInfOrNanReal(v[i]), PETSC_COMM_WORLD, PETSC_ERR_ARG_OUTOFRANGE, "%s: %s must be a finite number (got %s)", name, which, Number(v[i]).c_str());
    PetscCheck(r.Contains(v[i]), PETSC_COMM_WORLD, PETSC_ERR_ARG_OUTOFRANGE, "%s: %s must be %s (got %s)", name, which, r.Text().c_str(), Number(v[i]).c_str());
  }
  PetscFunctionReturn(0);
}

void OptionReader::Record(const char *name, OptionRole role, const std::string &value) const
{
  if (role == PROBLEM) problem[name] = value;
}

void OptionReader::Record(const char *name, OptionRole role, const PetscReal *v, PetscInt n) const
{
  std::string s;
  char        x[32];
  for (PetscInt i = 0; i < n; i++) {
    std::snprintf(x, sizeof(x), "%.15g", (double)v[i]); /* as given, for a person to compare */
    s += (i ? "," : "") + std::string(x);
  }
  Record(name, role, s);
}

PetscErrorCode OptionReader::Real(const char *name, const char *text, PetscReal *v, const Range &r, OptionRole role) const
{
  PetscBool given;

  PetscFunctionBegin;
  PetscCall(PetscOptionsReal(name, text, nullptr, *v, v, &given));
  if (given) PetscCall(Check(name, v, 1, r));
  Record(name, role, v, 1);
  PetscFunctionReturn(0);
}

PetscErrorCode OptionReader::Reals(const char *name, const char *text, PetscReal *v, PetscInt *n, PetscBool *set, const Range &r, OptionRole role) const
{
  const PetscInt max = *n;
  PetscBool      given;

  PetscFunctionBegin;
  PetscCall(PetscOptionsRealArray(name, text, nullptr, v, n, &given));
  if (given) PetscCall(Check(name, v, *n, r));
  Record(name, role, v, given ? *n : max);
  if (set) *set = given;
  PetscFunctionReturn(0);
}

PetscErrorCode OptionReader::Int(const char *name, const char *text, PetscInt *v, const Range &r, OptionRole role) const
{
  PetscReal x;
  PetscBool given;

  PetscFunctionBegin;
  PetscCall(PetscOptionsInt(name, text, nullptr, *v, v, &given));
  x = (PetscReal)*v;
  if (given) PetscCall(Check(name, &x, 1, r));
  Record(name, role, std::to_string(*v));
  PetscFunctionReturn(0);
}

PetscErrorCode OptionReader::String(const char *name, const char *text, char *v, size_t len, OptionRole role) const
{
  PetscFunctionBegin;
  PetscCall(PetscOptionsString(name, text, nullptr, v, v, len, nullptr));
  Record(name, role, v);
  PetscFunctionReturn(0);
}

PetscErrorCode OptionReader::Bool(const char *name, const char *text, PetscBool *v, OptionRole role) const
{
  PetscFunctionBegin;
  PetscCall(PetscOptionsBool(name, text, nullptr, *v, v, nullptr));
  Record(name, role, *v ? "true" : "false");
  PetscFunctionReturn(0);
}

PetscErrorCode OptionReader::Points(const char *name, const char *text, std::vector<PetscReal> &xyz) const
{
  PetscReal v[63] = {0}; /* room for a 21st point: PETSc drops values beyond the array silently */
  PetscInt  n     = 63;
  PetscBool set;

  PetscFunctionBegin;
  PetscCall(Reals(name, text, v, &n, &set, Any, RUN));
  PetscCheck(!set || n <= 60, PETSC_COMM_WORLD, PETSC_ERR_ARG_OUTOFRANGE, "%s: at most 20 points (got more than 20)", name);
  PetscCheck(!set || (n > 0 && n % 3 == 0), PETSC_COMM_WORLD, PETSC_ERR_ARG_WRONG, "%s: give x,y,z for each point (got %" PetscInt_FMT " values)", name, n);
  if (set) xyz.assign(v, v + n);
  PetscFunctionReturn(0);
}

PetscErrorCode OptionReader::CheckChoice(const char *name, const char *const *list, PetscInt n) const
{
  char      value[256];
  PetscBool given, known = PETSC_FALSE;

  PetscFunctionBegin;
  PetscCall(PetscOptionsGetString(PetscOptionsObject->options, PetscOptionsObject->prefix, name, value, sizeof(value), &given));
  if (!given) PetscFunctionReturn(0);
  std::string names;
  for (PetscInt i = 0; i < n; i++) {
    PetscBool same;
    PetscCall(PetscStrcasecmp(value, list[i], &same));
    known = (PetscBool)(known || same);
    names += (i ? ", " : "") + std::string(list[i]);
  }
  PetscCheck(known, PETSC_COMM_WORLD, PETSC_ERR_ARG_OUTOFRANGE, "%s %s is not one of: %s", name, value, names.c_str());
  PetscFunctionReturn(0);
}

PetscErrorCode OptionReader::Renamed(const char *old, const char *name) const
{
  PetscFunctionBegin;
  PetscCall(PetscOptionsDeprecated(old, name, "0.2", nullptr));
  PetscFunctionReturn(0);
}

} // namespace fsi
