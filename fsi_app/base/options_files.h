// SPDX-License-Identifier: BSD-2-Clause
/* Options files as fsi_app reads them, before PETSc starts: each `-options_file F` of the
   command line is replaced, in place, by the options F holds (one or more per line, `#` starts a
   comment), so an option given later still overrides an earlier one, as with PETSc's own reader.
   A path that a file names — an included file, -mesh, -restart, a waveform — is taken relative
   to that file's folder, or, if nothing is there, to the working directory: a scene and its
   meshes run from any folder, and from where they are installed (share/fsi_app). A file that
   includes itself, directly or through others, is refused with the chain of files (PETSc's
   reader would recurse until the stack overflows). */
#pragma once

#include <string>
#include <vector>

namespace fsi {

/* The command line args[1..] with every options file expanded; "" or the sentence that says
   which file cannot be read or which chain of includes closes a cycle. */
std::string ExpandOptionsFiles(std::vector<std::string> &args);

} // namespace fsi
