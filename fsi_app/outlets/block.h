// SPDX-License-Identifier: BSD-2-Clause
/* The outlets block: a 0D model of the vessels beyond each outlet of the fluid (the groups of
   -fluid_outlet), implicit in the monolithic Newton system. An outlet k with a model has three
   unknowns y_k = (Q_k, P_k, Pi_k) — its flow, its pressure, the pressure of its capacitor — a
   degree-0 field "outlets" on one fluid cell by the outlet (one rank owns them), and the rows
     flow            Q_k - int_{Gamma_k} u . n da = 0
     pressure        P_k - R_p Q_k - Pi_k = 0
     capacitor       resistance: Pi_k - P_d = 0
                     RCR:        C d_t Pi_k + (Pi_k - P_d) / R_d - Q_k = 0
                     pressure:   Pi_k - p(t) = 0 (and R_p = 0: P_k = p(t))
   with d_t the scene's time scheme (core/time_history.h), and in the fluid's momentum rows the
   traction -P_k n on Gamma_k: + P_k int_{Gamma_k} phi . n da. A resistance R is R_p = R; the
   three-element Windkessel (RCR) has R_p, C, R_d and the distal pressure P_d; a prescribed
   pressure p(t) (samples or a Fourier series) is the resistance 0 at P_d = p(t). An outlet without
   a model is traction-free. Each modelled outlet adds one dense row (its flow) and one dense
   column (its pressure) to the Jacobian. The unknowns form the split "outlets" after the fluid
   in FaCSI's multiplicative sweep: the fluid's step leaves out the P_k columns (a rank-one term
   per outlet: GMRES pays about one iteration for each), the outlets' step solves their rows
   exactly. The flow row's derivative in the mesh displacement is left out (the outlet's plane
   does not move; only its in-plane nodes do): on a moving mesh Newton is then a quasi-Newton
   method in those entries. Each step's (t, Q_k, P_k, Pi_k) go into the run report and, with
   -output NAME, into NAME_outlet_<group>.csv. */
#pragma once

#include "core/block.h"
#include "core/scene.h"
#include "base/waveform.h"
#include "discretization/probes.h"

namespace fsi {

enum OutletModel { OUTLET_FREE, OUTLET_RESISTANCE, OUTLET_RCR, OUTLET_PRESSURE };

struct Outlet {
  std::string group;
  OutletModel model = OUTLET_FREE;
  PetscReal   Rp = 0, C = 0, Rd = 0, Pd = 0; /* dyn s/cm^5, cm^5/dyn, dyn s/cm^5, dyn/cm^2 */
  PetscReal   P0 = 0;                        /* Pi at t = 0 (dyn/cm^2) */
  Waveform    pressure;                      /* OUTLET_PRESSURE: P(t) */
  /* set up: its faces among this rank's velocity cells, where its unknowns are */
  std::vector<CellFace> faces;
  PetscInt              local = -1;  /* the owner's local offset of Q (P, Pi follow); -1 elsewhere */
  PetscInt              global = -1; /* the global index of Q, on every rank */
  Probes                series;      /* (Q, P, Pi) per step, at the outlet's centre */
};

class OutletsBlock : public Block {
public:
  explicit OutletsBlock(const Scene &sc) : sc(sc) {}
  const char    *Name() const override { return "outlets"; }
  PetscErrorCode Wire(const std::vector<Block *> &scene) override;
  PetscErrorCode ReadOptions(std::map<std::string, std::string> &problem) override;
  void           Groups(std::vector<GroupUse> &) const override {} /* the fluid's -fluid_outlet */
  PetscInt       Field(const std::string &name) const override { return name == "outlets" ? field : -1; }

  PetscErrorCode AddFields(DM dm) override;
  PetscErrorCode SetUp(DM dm) override;
  void           Attach(SNES, const TimeHistory *h) override { history = h; }
  PetscErrorCode SetTime(PetscReal t) override { return time = t, 0; }

  PetscErrorCode Residual(const PetscScalar *x, PetscScalar *f) override;
  PetscErrorCode Jacobian(const PetscScalar *x, Mat P) override;
  void           Couplings(Sparsity &s) const override;
  PetscErrorCode InitialState(DM dm, Vec x, PetscBool *set) override;

  std::vector<PetscInt> SplitFields() const override { return {field}; }
  PetscInt              SplitPlace() const override { return 3; } /* after the fluid */
  void                  Unknowns(std::vector<std::pair<std::string, PetscInt>> &u) const override { u.push_back({"outlets", field}); }
  PetscErrorCode        AfterStep(DM dm, PetscInt step, PetscReal t, Vec x) override;
  PetscErrorCode        Results(DM dm, Vec x, PetscReal t, RunReport &report) override;

private:
  /* per modelled outlet, this rank's int phi_a . n_i da over its faces, by velocity dof */
  PetscErrorCode FaceWeights(const Outlet &o, const PetscScalar *x, std::vector<PetscReal> &b) const;

  const Scene        &sc;
  const Block        *fluid = nullptr, *geometry = nullptr;
  const FieldCells   *velocity = nullptr, *mesh = nullptr;
  const TimeHistory  *history = nullptr;
  FaceRule            rule;
  PetscInt            field = -1;
  PetscReal           time  = 0; /* of the step being solved */
  std::vector<Outlet> outlets; /* the modelled ones, in the order of -fluid_outlet */
};

} // namespace fsi
