// SPDX-License-Identifier: BSD-2-Clause
/* The wall's local frame from the vessel's centreline, the curve vessel-modelling tools give
   with a segmented artery (VMTK's centrelines, say): one polyline per branch. At a point X of
   the wall, P is the point of the centreline whose normal plane holds X (its cross-section; the
   nearest point where none does, beyond a branch's end); the axial direction e_a is the tangent
   there (a segment's direction, turned linearly towards the mean of the two segments' directions
   within half the shorter one's length of a shared point, so e_a turns continuously along a
   bent branch and a long straight segment keeps its direction), the radial one e_r = X - P without
   its axial part, normalised, and the circumferential one e_c = e_a x e_r. The arterial law's
   fibres lie at +-beta from e_c towards e_a. In a straight tube along z with the centreline
   (0,0,0)-(0,0,L) this is the frame about the z-axis exactly. A cell keeps the segment nearest
   to its centre; its points search that segment and four either side of it in the branch.

   The file: one point "x y z" per line (cm), a blank line between branches, '#' comments; a
   branch has at least 2 points, consecutive points differ. */
#pragma once

#include <petscsys.h>
#include <string>
#include <vector>

namespace fsi {

struct Centerline {
  std::vector<PetscReal> x;       /* 3 per point */
  std::vector<PetscInt>  branch;  /* per point */
  std::vector<PetscReal> tangent; /* 3 per point, unit */
};

/* Read on rank 0, checked, and sent to every rank; `option` names the option in messages. */
PetscErrorCode CenterlineRead(MPI_Comm comm, const char *option, const std::string &file, Centerline &c);

/* The segment (the index of its first point) nearest to X. */
PetscInt CenterlineNearest(const Centerline &c, const PetscReal X[3]);

/* The frame (e_a, e_r, e_c) at X from the segments of the branch next to segment s; false if X
   lies on the centreline (no radial direction). */
bool CenterlineFrame(const Centerline &c, PetscInt s, const PetscReal X[3], PetscReal frame[9]);

/* The two fibre families at +-beta from e_c towards e_a. */
void FrameFibres(const PetscReal frame[9], PetscReal beta, PetscReal a[6]);

} // namespace fsi
