// SPDX-License-Identifier: BSD-2-Clause
/* Time series beside the -output file, NAME_<what>.csv: a header line, then one row per step
   (its time first), written by rank 0 as the run goes, so the file is whole whenever the run
   stops. A run's first row makes the file: a fresh one, or after a restart the earlier rows
   of times before the row's kept (so every step is there once). */
#pragma once

#include <petscsys.h>
#include <string>
#include <vector>

namespace fsi {

/* NAME_<what>.csv for -output NAME.xdmf */
std::string CsvFile(const std::string &output, const std::string &what);

/* Append `row` to the series `what` of -output `output` (nothing without one). `first`: the
   run's first row; `restarted`: the run continues an earlier one. */
PetscErrorCode CsvAppend(const char *output, const std::string &what, const std::string &header, PetscBool first, PetscBool restarted, const std::vector<PetscReal> &row);

} // namespace fsi
