// SPDX-License-Identifier: BSD-2-Clause
/* -help with the whole prefix of gdsw's inner solvers.

   PETSc 3.18 prints a list-valued option (-pc_type, -ksp_type, -pc_factor_mat_ordering_type) as
   "-" + prefix + name, the first part built in a 64-byte buffer by PetscStrlcat(), which there
   appends at most 64 minus the length of the appended string: a prefix of more than 32 characters
   comes out cut to 64 minus its length. gdsw's inner prefixes are long under PCFIELDSPLIT
   (fieldsplit_structure_pc_gdsw_sub_: 33, printed -fieldsplit_structure_pc_gdsw_supc_type), and
   the user then reads an option that does not exist. While an inner solver reads its options
   under -help, PetscVFPrintf() passes through here and such a line gets the whole prefix back;
   every other line is printed as it was. Where PetscStrlcat() appends what fits, nothing changes. */
#include "../gdswimpl.h"
#include <cstdarg>
#include <string>

namespace {

/* PetscFunctionListPrintTypes()'s first line: "-" + prefix (cut short), name + 1, the values, the text */
const char ListLine[] = "  %s%s <now %s : formerly %s>: %s (one of)";

std::string whole;                                            /* "-" + the inner solver's prefix */
PetscErrorCode (*printer)(FILE *, const char[], va_list) = nullptr; /* PetscVFPrintf() outside */

bool PetscCutsPrefixes()
{
  char buf[8] = "-";
  return PetscStrlcat(buf, "abcdef", sizeof(buf)) || strcmp(buf, "-abcdef"); /* 7 characters fit in 8 bytes */
}

PetscErrorCode Print(FILE *fd, const char format[], ...)
{
  va_list ap;

  PetscFunctionBegin;
  va_start(ap, format);
  PetscErrorCode ierr = printer(fd, format, ap);
  va_end(ap);
  PetscCall(ierr);
  PetscFunctionReturn(0);
}

PetscErrorCode PrintWholePrefix(FILE *fd, const char format[], va_list ap)
{
  PetscFunctionBegin;
  if (strcmp(format, ListLine)) {
    PetscCall(printer(fd, format, ap));
    PetscFunctionReturn(0);
  }
  va_list args;
  va_copy(args, ap);
  const char *cut = va_arg(args, const char *), *name = va_arg(args, const char *), *now = va_arg(args, const char *), *before = va_arg(args, const char *), *text = va_arg(args, const char *);
  va_end(args);
  const bool shortened = strlen(cut) < whole.size() && !whole.compare(0, strlen(cut), cut);
  PetscCall(Print(fd, format, shortened ? whole.c_str() : cut, name, now, before, text));
  PetscFunctionReturn(0);
}

} // namespace

PetscErrorCode GDSWKSPSetFromOptions(KSP ksp)
{
  PetscBool      help;
  const char    *prefix;
  PetscErrorCode ierr;

  PetscFunctionBegin;
  PetscCall(PetscOptionsHasHelp(((PetscObject)ksp)->options, &help));
  PetscCall(KSPGetOptionsPrefix(ksp, &prefix));
  if (!help || !prefix || strlen(prefix) <= 32 || !PetscCutsPrefixes()) {
    PetscCall(KSPSetFromOptions(ksp));
    PetscFunctionReturn(0);
  }
  whole         = std::string("-") + prefix;
  printer       = PetscVFPrintf;
  PetscVFPrintf = PrintWholePrefix;
  ierr          = KSPSetFromOptions(ksp);
  PetscVFPrintf = printer;
  PetscCall(ierr);
  PetscFunctionReturn(0);
}
