/* The element-based decomposition that -pc_type gdsw gets from the application: METIS splits
   each rank's cells into subdomains; a subdomain's dofs are those in the closure of its cells. */
#pragma once

#include <petscdmplex.h>
#include <petscksp.h>

namespace fsi {

/* Attach the rigid-body near-null space of `field` to J; if pc is PCGDSW, also hand it
   `perRank` subdomains per rank: closure dofs of METIS parts of the local cells of group
   `region` ("" for all). */
PetscErrorCode SetGDSWSubdomains(PC pc, DM dm, Mat J, const char *region, PetscInt field, PetscInt perRank);

} // namespace fsi
