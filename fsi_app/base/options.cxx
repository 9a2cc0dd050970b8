// SPDX-License-Identifier: BSD-2-Clause
#include "base/options.h"
#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <set>

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

static std::set<std::string> &Known()
{
  static std::set<std::string> names;
  return names;
}

void KnownOption(const char *name)
{
  Known().insert(name);
}

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

PetscErrorCode OptionReader::Given(const char *name, const char *what, std::string &value, PetscBool *given) const
{
  char buf[4096] = "";

  PetscFunctionBegin;
  KnownOption(name);
  PetscCall(PetscOptionsGetString(PetscOptionsObject->options, PetscOptionsObject->prefix, name, buf, sizeof(buf), given));
  value = buf;
  /* PETSc keeps the default of a number given without its value: "-dt" alone would be statics */
  PetscCheck(!*given || !what || !value.empty(), PETSC_COMM_WORLD, PETSC_ERR_ARG_WRONG, "%s: give a value (%s)", name, what);
  PetscFunctionReturn(0);
}

PetscErrorCode OptionReader::Help(const char *name, const std::string &value, const std::string &def, const char *text, const std::string &range) const
{
  std::string note = range;

  PetscFunctionBegin;
  if (!PetscOptionsObject->printhelp || PetscOptionsObject->count != 1 || PetscOptionsObject->alreadyprinted) PetscFunctionReturn(0);
  if (value != def) note += (note.empty() ? "" : "; ") + std::string("default ") + (def.empty() ? "empty" : def);
  PetscCall((*PetscHelpPrintf)(PetscOptionsObject->comm, "  %s <%s>: %s%s\n", name, value.c_str(), text, note.empty() ? "" : (" (" + note + ")").c_str()));
  PetscFunctionReturn(0);
}

static std::string List(const PetscReal *v, PetscInt n)
{
  std::string s;
  for (PetscInt i = 0; i < n; i++) s += (i ? "," : "") + Number(v[i]);
  return s;
}

static std::string RangeNote(const Range &r)
{
  return PetscIsInfReal(r.lo) && PetscIsInfReal(r.hi) ? "" : r.Text();
}

PetscErrorCode OptionReader::Real(const char *name, const char *text, PetscReal *v, const Range &r, OptionRole role) const
{
  const std::string def = Number(*v), what = "a number" + (RangeNote(r).empty() ? "" : ", " + RangeNote(r));
  std::string       value;
  PetscBool         given;

  PetscFunctionBegin;
  PetscCall(Given(name, what.c_str(), value, &given));
  if (given) PetscCall(PetscOptionsGetReal(PetscOptionsObject->options, PetscOptionsObject->prefix, name, v, nullptr));
  if (given) PetscCall(Check(name, v, 1, r));
  PetscCall(Help(name, Number(*v), def, text, what));
  Record(name, role, v, 1);
  PetscFunctionReturn(0);
}

PetscErrorCode OptionReader::Reals(const char *name, const char *text, PetscReal *v, PetscInt *n, PetscBool *set, const Range &r, OptionRole role) const
{
  const PetscInt    max = *n;
  const std::string def = List(v, max), what = "numbers separated by commas" + (RangeNote(r).empty() ? "" : ", each " + RangeNote(r));
  std::string       value;
  PetscBool         given;

  PetscFunctionBegin;
  PetscCall(Given(name, what.c_str(), value, &given));
  /* PETSc reads the first max values and drops the rest without a word */
  const PetscInt count = given ? (PetscInt)std::count(value.begin(), value.end(), ',') + 1 : 0;
  PetscCheck(count <= max, PETSC_COMM_WORLD, PETSC_ERR_ARG_WRONG, "%s %s: give at most %" PetscInt_FMT " values (got %" PetscInt_FMT ")", name, value.c_str(), max, count);
  if (given) PetscCall(PetscOptionsGetRealArray(PetscOptionsObject->options, PetscOptionsObject->prefix, name, v, n, nullptr));
  if (given) PetscCall(Check(name, v, *n, r));
  PetscCall(Help(name, List(v, given ? *n : max), def, text, what));
  Record(name, role, v, given ? *n : max);
  if (set) *set = given;
  PetscFunctionReturn(0);
}

/* An integer as written, or a whole number in floating point ("1e3"), that a PetscInt holds:
   PETSc's own parser wraps 4294967297 to 1. */
static PetscErrorCode ParseInt(const char *name, const std::string &value, PetscInt *v)
{
  char       *end = nullptr;
  long long   i;
  double      d;
  const char *s = value.c_str();

  PetscFunctionBegin;
  errno = 0;
  i     = std::strtoll(s, &end, 10);
  if (*end || errno == ERANGE) { /* not a plain integer: a whole number written as a real? */
    d = std::strtod(s, &end);
    PetscCheck(!*end && end != s && d == (double)(long long)d, PETSC_COMM_WORLD, PETSC_ERR_ARG_WRONG, "%s: value must be an integer (got %s)", name, s);
    PetscCheck(PetscAbsReal(d) <= (PetscReal)PETSC_MAX_INT, PETSC_COMM_WORLD, PETSC_ERR_ARG_OUTOFRANGE, "%s: value must be at most %d in size (got %s)", name, PETSC_MAX_INT, s);
    i = (long long)d;
  }
  PetscCheck(end != s, PETSC_COMM_WORLD, PETSC_ERR_ARG_WRONG, "%s: value must be an integer (got %s)", name, s);
  PetscCheck(i <= (long long)PETSC_MAX_INT && i >= -(long long)PETSC_MAX_INT, PETSC_COMM_WORLD, PETSC_ERR_ARG_OUTOFRANGE, "%s: value must be at most %d in size (got %s)", name, PETSC_MAX_INT, s);
  *v = (PetscInt)i;
  PetscFunctionReturn(0);
}

PetscErrorCode OptionReader::Int(const char *name, const char *text, PetscInt *v, const Range &r, OptionRole role) const
{
  const std::string def = std::to_string(*v), what = "an integer" + (RangeNote(r).empty() ? "" : ", " + RangeNote(r));
  std::string       value;
  PetscReal         x;
  PetscBool         given;

  PetscFunctionBegin;
  PetscCall(Given(name, what.c_str(), value, &given));
  if (given) {
    PetscCall(ParseInt(name, value, v));
    x = (PetscReal)*v;
    PetscCall(Check(name, &x, 1, r));
  }
  PetscCall(Help(name, std::to_string(*v), def, text, what));
  Record(name, role, std::to_string(*v));
  PetscFunctionReturn(0);
}

PetscErrorCode OptionReader::String(const char *name, const char *text, char *v, size_t len, OptionRole role) const
{
  const std::string def = v;
  std::string       value;
  PetscBool         given;

  PetscFunctionBegin;
  PetscCall(Given(name, nullptr, value, &given));
  PetscCheck(value.size() < len, PETSC_COMM_WORLD, PETSC_ERR_ARG_OUTOFRANGE, "%s: the value is %zu characters long, at most %zu are kept", name, value.size(), len - 1);
  if (given) PetscCall(PetscStrncpy(v, value.c_str(), len));
  PetscCall(Help(name, v, def, text, ""));
  Record(name, role, v);
  PetscFunctionReturn(0);
}

PetscErrorCode OptionReader::Bool(const char *name, const char *text, PetscBool *v, OptionRole role) const
{
  const std::string def = *v ? "true" : "false";
  std::string       value;
  PetscBool         given;

  PetscFunctionBegin;
  PetscCall(Given(name, nullptr, value, &given));
  if (given && !value.empty()) { /* PETSc's own refusal does not name the option */
    PetscBool known = PETSC_FALSE;
    for (const char *word : {"true", "false", "yes", "no", "on", "off", "1", "0"})
      if (!known) PetscCall(PetscStrcasecmp(value.c_str(), word, &known));
    PetscCheck(known, PETSC_COMM_WORLD, PETSC_ERR_ARG_WRONG, "%s %s is not true or false", name, value.c_str());
  }
  if (given) PetscCall(PetscOptionsGetBool(PetscOptionsObject->options, PetscOptionsObject->prefix, name, v, nullptr)); /* alone: true */
  PetscCall(Help(name, *v ? "true" : "false", def, text, "true or false; alone: true"));
  Record(name, role, *v ? "true" : "false");
  PetscFunctionReturn(0);
}

PetscErrorCode OptionReader::Numbers(const char *name, const char *text, std::vector<PetscReal> &v, PetscInt max, const char *what, OptionRole role) const
{
  std::vector<PetscReal> x(max);
  PetscInt               n = max;
  std::string            value;
  PetscBool              given;

  PetscFunctionBegin;
  PetscCall(Given(name, what, value, &given));
  /* PETSc reads the first max values and drops the rest without a word */
  const PetscInt count = given ? (PetscInt)std::count(value.begin(), value.end(), ',') + 1 : 0;
  PetscCheck(count <= max, PETSC_COMM_WORLD, PETSC_ERR_ARG_WRONG, "%s %s: give at most %" PetscInt_FMT " values (got %" PetscInt_FMT ")", name, value.c_str(), max, count);
  if (given) PetscCall(PetscOptionsGetRealArray(PetscOptionsObject->options, PetscOptionsObject->prefix, name, x.data(), &n, nullptr));
  if (given) PetscCall(Check(name, x.data(), n, Any));
  if (given) v.assign(x.begin(), x.begin() + n);
  PetscCall(Help(name, List(v.data(), (PetscInt)v.size()), "", text, what));
  Record(name, role, v.data(), (PetscInt)v.size());
  PetscFunctionReturn(0);
}

PetscErrorCode OptionReader::Points(const char *name, const char *text, std::vector<PetscReal> &xyz) const
{
  PetscFunctionBegin;
  PetscCall(Numbers(name, text, xyz, 63, "x,y,z of each point, separated by commas; cm", RUN)); /* room for a 21st point */
  PetscCheck(xyz.size() <= 60, PETSC_COMM_WORLD, PETSC_ERR_ARG_OUTOFRANGE, "%s: at most 20 points (got more than 20)", name);
  PetscCheck(xyz.size() % 3 == 0, PETSC_COMM_WORLD, PETSC_ERR_ARG_WRONG, "%s: give x,y,z for each point (got %zu values)", name, xyz.size());
  PetscFunctionReturn(0);
}

PetscErrorCode OptionReader::Choice(const char *name, const char *text, const char *const *list, PetscInt *v, OptionRole role) const
{
  const PetscInt def = *v;
  PetscInt       n   = 0;
  std::string    value, names;
  PetscBool      given;

  PetscFunctionBegin;
  while (list[n + 2]) n++; /* PETSc's enum lists end with the type name, the prefix and a null */
  for (PetscInt i = 0; i < n; i++) names += (i ? ", " : "") + std::string(list[i]);
  PetscCall(Given(name, ("one of: " + names).c_str(), value, &given));
  if (given) {
    PetscInt k = 0;
    for (PetscBool same = PETSC_FALSE; k < n; k++) {
      PetscCall(PetscStrcasecmp(value.c_str(), list[k], &same));
      if (same) break;
    }
    PetscCheck(k < n, PETSC_COMM_WORLD, PETSC_ERR_ARG_OUTOFRANGE, "%s %s is not one of: %s", name, value.c_str(), names.c_str());
    *v = k;
  }
  PetscCall(Help(name, list[*v], list[def], text, "one of: " + names));
  Record(name, role, list[*v]);
  PetscFunctionReturn(0);
}

PetscErrorCode OptionReader::Renamed(const char *old, const char *name) const
{
  PetscFunctionBegin;
  KnownOption(old);
  PetscCall(PetscOptionsDeprecated(old, name, "0.2", nullptr));
  PetscFunctionReturn(0);
}

/* Levenshtein's distance: letters inserted, deleted or replaced. */
static size_t Distance(const std::string &a, const std::string &b)
{
  std::vector<size_t> row(b.size() + 1);
  for (size_t j = 0; j <= b.size(); j++) row[j] = j;
  for (size_t i = 1; i <= a.size(); i++) {
    size_t diag = row[0];
    row[0]      = i;
    for (size_t j = 1; j <= b.size(); j++) {
      const size_t up = row[j];
      row[j]          = std::min(std::min(row[j], row[j - 1]) + 1, diag + (a[i - 1] != b[j - 1] ? 1 : 0));
      diag            = up;
    }
  }
  return row[b.size()];
}

PetscErrorCode CheckUnusedOptions(MPI_Comm comm, const std::vector<std::string> &prefixes)
{
  PetscInt    n;
  char      **names, **values;
  std::string sentence;

  PetscFunctionBegin;
  PetscCall(PetscOptionsLeftGet(nullptr, &n, &names, &values));
  for (PetscInt i = 0; i < n && sentence.empty(); i++) {
    const std::string name = std::string("-") + (names[i][0] == '-' ? names[i] + 1 : names[i]);
    std::string       closest;
    size_t            best = std::string::npos;
    for (const std::string &k : Known()) {
      const size_t d = Distance(name, k);
      if (d < best) best = d, closest = k;
    }
    const bool ours = std::any_of(prefixes.begin(), prefixes.end(), [&](const std::string &p) { return name.compare(1, p.size(), p) == 0; });
    const bool near = best <= (name.size() > 6 ? 2u : 1u);
    if (ours || near) sentence = name + ": no such option; did you mean " + closest + "? (-help lists every option)";
  }
  PetscCall(PetscOptionsLeftRestore(nullptr, &n, &names, &values));
  PetscCheck(sentence.empty(), comm, PETSC_ERR_ARG_WRONG, "%s", sentence.c_str());
  PetscFunctionReturn(0);
}

} // namespace fsi
