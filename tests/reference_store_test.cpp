// A reference as a database row and back (engine/reference_store.h): every value the row keeps
// comes back as the run held it, and a row stored before the estimate's parts were takes the
// whole estimate as each part's bound.

#include <gtest/gtest.h>

#include "compare/reference_run.h"
#include "engine/reference_store.h"

namespace shockmap {
namespace {

ReferenceRun SmallReference() {
  CantileverImpact problem;
  problem.r_k = 3000.0;
  ReferenceOptions options;
  options.r_fref = 300.0;
  ShockSegmentationOptions shocks;
  shocks.rest_duration_s = 0.1 / problem.F1Hz();
  return ComputeReferenceRun(problem, options, 0.03, shocks);
}

TEST(ReferenceStore, ARowGivesBackTheRunItWasMadeFrom) {
  const ReferenceRun run = SmallReference();
  ASSERT_FALSE(run.shocks.empty());
  const ReferenceRow row = ToReferenceRow(run, "key", 3000.0, 0.03);
  EXPECT_EQ(row.reference_key, "key");
  EXPECT_EQ(row.r_k, 3000.0);
  EXPECT_EQ(row.window_s, 0.03);
  const ReferenceRun back = FromReferenceRow(row, "test.db");
  EXPECT_EQ(back.tip_m.values, run.tip_m.values);
  EXPECT_EQ(back.force_n.values, run.force_n.values);
  EXPECT_EQ(back.tip_m.dt_s, run.tip_m.dt_s);
  EXPECT_EQ(back.force_n.dt_s, run.force_n.dt_s);
  EXPECT_EQ(back.tip_m.t0_s, 0.0);
  EXPECT_EQ(back.convergence.r_fref, run.convergence.r_fref);
  EXPECT_EQ(back.convergence.r_fref_check, run.convergence.r_fref_check);
  EXPECT_EQ(back.convergence.difference, run.convergence.difference);
  EXPECT_EQ(back.convergence.tip.error, run.convergence.tip.error);
  EXPECT_EQ(back.convergence.impulse.error, run.convergence.impulse.error);
  EXPECT_EQ(back.convergence.induced_err.error, run.convergence.induced_err.error);
  EXPECT_EQ(back.summary.n_modes_free, run.summary.n_modes_free);
  EXPECT_EQ(back.summary.n_modes_contact, run.summary.n_modes_contact);
  EXPECT_EQ(back.summary.n_transitions, run.summary.n_transitions);
  EXPECT_EQ(back.wall_s, run.wall_s);
  ASSERT_EQ(back.shocks.size(), run.shocks.size());
  for (std::size_t i = 0; i < run.shocks.size(); ++i) {
    EXPECT_EQ(back.shocks[i].start_s, run.shocks[i].start_s);
    EXPECT_EQ(back.shocks[i].impulse_n_s, run.shocks[i].impulse_n_s);
    EXPECT_EQ(back.shocks[i].peak_force_n, run.shocks[i].peak_force_n);
    EXPECT_EQ(back.shocks[i].n_contacts, run.shocks[i].n_contacts);
  }
}

TEST(ReferenceStore, ARowWithoutTheEstimatesPartsBoundsEachByTheWhole) {
  ReferenceRow row = ToReferenceRow(SmallReference(), "key", 3000.0, 0.03);
  row.convergence = 0.25;
  row.estimate_tip.reset();
  row.estimate_impulse.reset();
  row.estimate_err.reset();
  const ReferenceRun back = FromReferenceRow(row, "test.db");
  EXPECT_EQ(back.convergence.difference, 0.25);
  EXPECT_EQ(back.convergence.tip.error, 0.25);
  EXPECT_EQ(back.convergence.impulse.error, 0.25);
  EXPECT_EQ(back.convergence.induced_err.error, 0.25);
}

}  // namespace
}  // namespace shockmap
