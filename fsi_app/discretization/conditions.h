// SPDX-License-Identifier: BSD-2-Clause
/* Essential conditions, owned by the application: a list of (field, faces, components, value)
   that builds the local section's constraints (constrained dofs leave the global system) and
   that InsertEssentialValues() reads to write the values into local vectors. PETSc 3.18's
   DMAddBoundary() cannot constrain a field that lives on a second region ("Field 1 is not in
   [0, 1)"), and a region DS's boundary constrains nothing, so the coupled problem, whose
   fields live on the fluid, the wall and the interface, cannot use it. Conditions between
   fields (d_f = d_s, u = d_t d_s on the interface) are not here: they are rows of the coupling
   block. */
#pragma once

#include <functional>
#include <map>
#include <petscdmplex.h>
#include <string>
#include <vector>

namespace fsi {

/* The nc values of a field at node position x and time t. */
using NodalValue = std::function<void(const PetscReal x[3], PetscReal t, PetscScalar *v)>;

struct Condition {
  std::string           name;  /* what set it, for messages: "-structure_clamp wall_inlet_ring" */
  PetscInt              field = -1;
  DMLabel               label = nullptr; /* the condition holds on the closure of its points */
  std::vector<PetscInt> values;          /* of the label; empty: every value */
  std::vector<PetscInt> comps;           /* components fixed; empty: all */
  NodalValue            value;           /* empty: zero */
  DMLabel               except = nullptr; /* not on the closure of its points (the nodes another block's rows fix) */
};

/* In the order added: where two conditions fix the same dof, the later one's value is written. */
using Conditions = std::vector<Condition>;

/* Field `field` = the constant vector `value` (nullptr: zero; it must outlive dm) on the faces
   of each comma-separated group: "a,b:xz" fixes every component on a, only x and z on b.
   `option` names the option in error messages. */
PetscErrorCode AddDirichlet(DM dm, Conditions &list, const char *groups, PetscInt field, const char *option, const PetscReal *value = nullptr);

/* The mesh points (sorted, local) a condition holds on: the closure of its label's points. */
PetscErrorCode ConditionPoints(DM dm, const Condition &c, std::vector<PetscInt> &points);

/* The components of field `field` (nc of them) the list fixes, per mesh point: bit k for
   component k. */
PetscErrorCode ConstrainedComponents(DM dm, const Conditions &list, PetscInt field, PetscInt nc, std::map<PetscInt, unsigned> &mask);

/* The local section of dm's fields (Lagrange P1 or P2 on their regions, as DMSetField() gave
   them; degree 0: a few scalars on each cell of the region, a 0D model's unknowns) with the list's constraints; dm keeps the list for InsertEssentialValues(). Call once,
   after every field and condition, before any vector or matrix is made. */
PetscErrorCode CreateSection(DM dm, const Conditions &list);

/* Write every condition's values at time t into the constrained dofs of a local vector. */
PetscErrorCode InsertEssentialValues(DM dm, PetscReal t, Vec local);

} // namespace fsi
