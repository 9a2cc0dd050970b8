// SPDX-License-Identifier: BSD-2-Clause
/* A block of the monolithic system (structure, fluid, geometry, coupling): it owns everything
   about itself — its fields, essential conditions, cells, rows of the residual and Jacobian,
   its split of the preconditioner, its output and its verification. A scene is a list of
   blocks (run/registry.h); the application only sums them. The stages are called in this
   order: Wire (every block exists), ReadOptions, Check, Groups (before the mesh is read),
   AddFields, AddConditions (every field exists), SetUp (the section exists), then per step
   SetTime, Predict, residuals and Jacobians, AfterStep; Results at the end. Blocks talk to
   each other only through this contract (Group, Field, Cells, Motion): no block reads another's
   members, so a block can be replaced without editing its partners. */
#pragma once

#include "discretization/cells.h"
#include "discretization/conditions.h"
#include "io/report.h"
#include "io/xdmf.h"
#include "mesh/mesh.h"
#include "core/sparsity.h"
#include "core/split_setup.h"
#include "core/time_history.h"
#include <petscsnes.h>
#include <map>
#include <string>
#include <vector>

namespace fsi {

struct PrescribedMotion; /* verification/mms.h */

/* The role of -structure_region and -fluid_region (GroupUse): the two must be different groups. */
inline const char *const RegionsRole = "regions of the wall and the fluid";

/* What a run's summary line and report give of the solution: the largest value of a field
   (max_<name>) and, under the name `norm`, the 2-norm of that field or of the whole solution. */
struct Headline {
  std::string name;
  PetscInt    field;
  std::string norm;
  PetscBool   whole = PETSC_FALSE;
};

class Block {
public:
  virtual ~Block() = default;
  virtual const char *Name() const = 0;
  /* The scene's other blocks, before any reads its options: a block finds the ones it works
     with (the fluid moves with the geometry; the coupling ties three). */
  virtual PetscErrorCode Wire(const std::vector<Block *> &scene) { return 0; }
  /* Its options, read and checked once under its own -help title (the blocks in the scene's
     order); the ones that define the problem go into `problem`. */
  virtual PetscErrorCode ReadOptions(std::map<std::string, std::string> &problem) = 0;
  /* Its options fit those of the blocks it works with (every block has read its own). */
  virtual PetscErrorCode Check() const { return 0; }
  /* The mesh groups its options name (checked when the mesh is read), and its region ("": none,
     or the whole mesh): the partition balances the cells of every region. */
  virtual void Groups(std::vector<GroupUse> &groups) const = 0;
  std::string  Region() const { return Group("region"); }

  /* What its partners may ask of it: the group it gives a role ("region", "interface",
     "noslip", "inlet", "outlet"; "" if none), the number of its field `name` in the DM (-1 if
     it has none; valid after AddFields), that field's cells (after SetUp), and the interface
     motion it prescribes (a mesh moved by a given wall: the manufactured flows' data). */
  virtual std::string             Group(const std::string &role) const { return ""; }
  virtual PetscInt                Field(const std::string &name) const { return -1; }
  virtual const FieldCells       *Cells(const std::string &name) const { return nullptr; }
  virtual const PrescribedMotion *Motion() const { return nullptr; }

  virtual PetscErrorCode AddFields(DM dm) = 0;
  virtual PetscErrorCode AddConditions(DM dm, Conditions &list) { return 0; }
  virtual PetscErrorCode SetUp(DM dm) = 0;
  /* The Newton solver (told when a cell inverts) and the time scheme's past states. */
  virtual void Attach(SNES snes, const TimeHistory *history) {}

  /* Its rows: add to the local residual f and into the matrix P (local state x). */
  virtual PetscErrorCode Residual(const PetscScalar *x, PetscScalar *f) = 0;
  virtual PetscErrorCode Jacobian(const PetscScalar *x, Mat P) = 0;
  /* The index blocks of its Jacobian's MatSetValues calls, without values: the matrix's layout. */
  virtual void Couplings(Sparsity &s) const = 0;
  virtual PetscErrorCode SetTime(PetscReal t) { return 0; }
  /* The first iterate of the step to time t (global x holds the last state). */
  virtual PetscErrorCode Predict(PetscReal t, Vec x) { return 0; }
  /* The state at t = 0, held since t = -infinity (global x is zero on entry); *set if it is not zero. */
  virtual PetscErrorCode InitialState(DM dm, Vec x, PetscBool *set) { return *set = PETSC_FALSE, 0; }

  /* Its part of PCFIELDSPLIT: these fields, in the split of this name (blocks may share one),
     and the split's place in the multiplicative composition (lower first; the owner's counts). */
  virtual std::vector<PetscInt> SplitFields() const = 0;
  virtual const char           *SplitName() const { return Name(); }
  virtual PetscInt              SplitPlace() const { return 0; }
  /* Linear rows (a dynamic scene of linear blocks factors its operator once); rows that are
     the gradient of an energy (the critical-point line search applies). */
  virtual PetscBool Linear() const { return PETSC_FALSE; }
  /* A Jacobian that depends on neither the state nor the time nor the step (the harmonic
     extension's): assembled once, its values kept (core/constant_rows.h). */
  virtual PetscBool ConstantJacobian() const { return PETSC_FALSE; }
  virtual PetscBool HasEnergy() const { return PETSC_FALSE; }
  /* Rows with no diagonal entry (a Lagrange multiplier's): PETSc's default ILU cannot factor them. */
  virtual PetscBool RowsWithoutDiagonal() const { return PETSC_FALSE; }
  /* The preconditioner of its rows: pc solves them (the whole system when the block is the
     scene's only one, its split of PCFIELDSPLIT otherwise) and dm holds exactly that split's
     fields; *nsp (or NULL) is the rows' near-null space, attached by the caller. */
  virtual PetscErrorCode ConfigurePC(DM dm, PC pc, MatNullSpace *nsp) { return *nsp = nullptr, 0; }
  /* How often its split's preconditioner is rebuilt (the split's rows change with the state);
     with SETUP_EVERY_STEP, at every SetUpInterval()-th time step only. */
  virtual SplitSetUp SetUpPolicy() const { return SETUP_EVERY_NEWTON; }
  virtual PetscInt   SetUpInterval() const { return 1; }

  virtual void Output(std::vector<OutputPart> &parts) const {}
  /* Its unknowns as the run reports them: (name, field). */
  virtual void Unknowns(std::vector<std::pair<std::string, PetscInt>> &u) const = 0;
  /* The summary line's field (the first block's that has one). */
  virtual PetscBool Summary(Headline *h) const { return PETSC_FALSE; }
  /* Why the last residual had no value (an inverted cell), "" if it had. */
  virtual std::string InvertedCause() const { return ""; }
  virtual PetscErrorCode AfterStep(DM dm, PetscInt step, PetscReal t, Vec x) { return 0; }
  /* Sums over the steps that its output carries on (this rank's part; a time average, say):
     a checkpoint keeps them, a restart continues from them. nullptr: none. */
  virtual std::vector<PetscReal> *RunningSums() { return nullptr; }
  virtual PetscErrorCode Results(DM dm, Vec x, PetscReal t, RunReport &report) { return 0; }
};

/* The block named `name` among `scene` (nullptr: the scene has none). */
inline Block *FindBlock(const std::vector<Block *> &scene, const char *name)
{
  for (Block *b : scene)
    if (std::string(b->Name()) == name) return b;
  return nullptr;
}

} // namespace fsi
