#pragma once
// Advice checked on an ensemble (docs/ensembles.md, "Advice checked on the bundle"): the study
// that runs an ensemble study's members at the settings `advise` gives for its scene
// (validation/scene_advice.h), at one coarser and at finer ones, on the same draws. Each rung of
// the ladder scales every beam's advised truncation by a factor (1/3, 1, 3, 9, ...) with a mesh
// that resolves it, at the advised dt / dt_sharp; the finest rung is the refined setting.

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "core/scene.h"
#include "validation/scene_advice.h"

namespace shockmap {

// The ladder's factors on the advised truncations, coarsest first: 1/3, 1, then 3^k up to
// `rungs` rungs in all.
std::vector<double> LadderFactors(int rungs);

// Whether every beam's advised truncation times `factor` stays within 1e5, the largest a scene
// file takes.
bool RungFits(const SceneAdvice& advice, double factor);

// Throws InputError naming `criteria_file` and the fit it holds (`criteria_json`'s fit.c and
// fit.p) when a beam's advised truncation times `factor`, the ladder's lowest rung, falls below
// 1, the least a scene file takes: the advice cannot be checked below itself.
void CheckLowestRung(const SceneAdvice& advice, double factor, const std::string& criteria_file,
                     const nlohmann::json& criteria_json);

// The setting of one rung, by path: each beam's advised truncation times `factor` (a bundle's
// pins share the largest of theirs: "bundle.pin.r_ftrunc"; the wrapper "bundle.wrapper.
// r_ftrunc"; a listed beam "beams[i].r_ftrunc"), its mesh at least the scene's and fine enough
// for the truncated mode (core/cantilever_impact.h DefaultElementCount), and
// "solver.dt.factor" at the advised dt / dt_sharp. Throws InputError when a truncation would
// exceed 1e5 (the scene file's largest) or the scene's dt is not a rule of the sharp bound.
// `scene_json` is the scene file's JSON, `scene` the scene it parses to.
nlohmann::json RungSetting(const nlohmann::json& scene_json, const Scene& scene,
                           const SceneAdvice& advice, double factor);

// What an advice-check study records of its ladder ("advice_check" in the study file): each
// listed setting's factor on the advised truncations, the advised rung, and the sizing quantile
// and tolerance the check judges at (so that the report gives the same verdict).
struct AdviceCheckRecord {
  std::vector<double> factors;
  int advised = 1;
  double quantile = 0.95, tolerance = 0.05;
};
nlohmann::json AdviceCheckRecordJson(const AdviceCheckRecord& record);
// Throws InputError naming `file` and `where` unless the factors are positive and increasing,
// one per setting (`settings`), the advised rung one of them, the quantile in (0, 1) and the
// tolerance in [0, 1].
AdviceCheckRecord ParseAdviceCheckRecord(const nlohmann::json& json, const std::string& file,
                                         const std::string& where, std::size_t settings);

// The ensemble study `ensemble` (its JSON, from `file`) as the ladder's study: named
// "<name>_advice_check", its scene by absolute path, the rung settings listed coarsest first
// (the finest refined), the keys they set written into the scene where it left them at their
// default ("scene_set"), `members` members per state and rung and a window of `window_s` seconds
// when positive (else the study file's), and the ladder recorded ("advice_check", record.factors
// its factors).
nlohmann::json AdviceCheckStudy(const nlohmann::json& ensemble, const std::string& file,
                                const nlohmann::json& scene_json, const Scene& scene,
                                const SceneAdvice& advice, const AdviceCheckRecord& record,
                                int members, double window_s);

}  // namespace shockmap
