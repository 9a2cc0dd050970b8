// SPDX-License-Identifier: BSD-2-Clause
#include "csv.h"
#include "xdmf.h"
#include <cstdlib>
#include <fstream>

namespace fsi {

std::string CsvFile(const std::string &output, const std::string &what)
{
  const std::string xdmf = XdmfPartFile(output, what);
  return xdmf.substr(0, xdmf.size() - 5) + ".csv";
}

PetscErrorCode CsvAppend(const char *output, const std::string &what, const std::string &header, PetscBool first, PetscBool restarted, const std::vector<PetscReal> &row)
{
  PetscMPIInt rank;

  PetscFunctionBegin;
  PetscCallMPI(MPI_Comm_rank(PETSC_COMM_WORLD, &rank));
  if (!output[0] || rank || row.empty()) PetscFunctionReturn(0);
  const std::string file = CsvFile(output, what);
  if (first) {
    std::vector<std::string> keep;
    if (restarted) {
      std::ifstream in(file);
      for (std::string line; std::getline(in, line);)
        if (!line.empty() && line != header && std::strtod(line.c_str(), nullptr) < row[0] - 1e-12) keep.push_back(line);
    }
    std::ofstream out(file, std::ios::trunc);
    out << header << "\n";
    for (const std::string &l : keep) out << l << "\n";
    PetscCheck(out.good(), PETSC_COMM_SELF, PETSC_ERR_FILE_WRITE, "-output %s: cannot write %s", output, file.c_str());
  }
  std::ofstream out(file, std::ios::app);
  char          v[32];
  for (size_t k = 0; k < row.size(); k++) {
    PetscSNPrintf(v, sizeof(v), "%s%.10e", k ? "," : "", (double)row[k]);
    out << v;
  }
  out << "\n";
  PetscCheck(out.good(), PETSC_COMM_SELF, PETSC_ERR_FILE_WRITE, "-output %s: cannot write %s", output, file.c_str());
  PetscFunctionReturn(0);
}

} // namespace fsi
