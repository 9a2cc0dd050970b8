// SPDX-License-Identifier: BSD-2-Clause
/* The element-based decomposition that -pc_type gdsw gets from the application: METIS splits
   each rank's cells into subdomains; a subdomain's dofs are those in the closure of its cells. */
#pragma once

#include <petscdmplex.h>
#include <petscksp.h>

namespace fsi {

/* If pc is PCGDSW, hand it `perRank` subdomains per rank (the closure dofs of METIS parts of
   the local cells of group `region`, "" for all) and the nodes' coordinates, both in dm's
   numbering: the whole system's or a split's sub-DM. dm holds one vector field of 3
   components whose nodes are free or clamped as a whole. */
PetscErrorCode ConfigureGDSW(PC pc, DM dm, const char *region, PetscInt perRank);

} // namespace fsi
