// SPDX-License-Identifier: BSD-2-Clause
/* One thread per MPI rank during the set-up's factorisations.

   gdsw's parallelism is its subdomains over the MPI ranks. CHOLMOD as SuiteSparse 5 builds it
   opens OpenMP teams of a fixed 4 threads (num_threads(CHOLMOD_OMP_NUM_THREADS)) to clear its
   workspace and zero each supernode, whatever OMP_NUM_THREADS says: with one rank per core those
   threads take cores from the other ranks and cost a futex wake-up per supernode. With the
   runtime's max-active-levels at 0 every parallel region the set-up opens runs on the calling
   thread. A user who asked for threads (OMP_NUM_THREADS above 1) keeps the runtime as it is. */
#include "../gdswimpl.h"
#include <cstdlib>
#include <omp.h>

PetscErrorCode GDSWSerialRegionsBegin(PetscInt *saved)
{
  PetscFunctionBegin;
  *saved = -1;
  const char *env = std::getenv("OMP_NUM_THREADS");
  if (env && std::atoi(env) > 1) PetscFunctionReturn(0);
  *saved = (PetscInt)omp_get_max_active_levels();
  omp_set_max_active_levels(0);
  PetscFunctionReturn(0);
}

PetscErrorCode GDSWSerialRegionsEnd(PetscInt saved)
{
  PetscFunctionBegin;
  if (saved >= 0) omp_set_max_active_levels((int)saved);
  PetscFunctionReturn(0);
}
