// JSON documents of the discovery statistics, shared by the Lua binding (paddy.doe.*) and the
// command line (`paddy doe diagnose`). Field names and layout: docs/doe.md, "Naming a missing
// effect". Every function validates its document and throws DoeError naming the field.
//   noiseCovarianceJson {replicates = n x m, sigma = m, n_avg, measurement_covariance = m x m}  -> {covariance, shrinkage, seed_sd, ...}
//   diagnoseJson        {residual, covariance | sigma, jacobian, candidates, labels, blocks, alpha, ...}
//   gaussNewtonJson     {theta, residual, jacobian, covariance | sigma, lower, upper, damping}
//   compareFitsJson     {q_before, q_after, df, n, k_before, k_after}
//   compareNonNestedJson {residual_a, residual_b, covariance, k_a, k_b, alpha} -> {lr, omega, z, p, preferred} (non_nested.hpp)
//   responseSurfaceJson {points, values, measured, covariance | sigma, lower, upper}
//                       -> {x, predicted, jacobian, covariance, se, residual_sd, misfit_predicted, terms, coefficients, at_bound}
//                       (response_surface.hpp)
//   nullThresholdsJson  {z_max = {...}, q0 = {...}, q_after = {...}, alpha}
//   bootstrapThresholdsJson {seed_covariance, replicates, n_avg, sigma, measurement_covariance, jacobian, candidates, alpha, trials, seed}
//                       -> the same fields as nullThresholdsJson (bootstrap_null.hpp)
#pragma once
#include "paddy/doe/discovery.hpp"

#include <nlohmann/json.hpp>
#include <ostream>

namespace paddy::doe {

nlohmann::json noiseCovarianceJson(const nlohmann::json& in);
DiagnoseInput diagnoseInputFromJson(const nlohmann::json& in);
nlohmann::json diagnosisToJson(const Diagnosis& d);
nlohmann::json diagnoseJson(const nlohmann::json& in);
nlohmann::json gaussNewtonJson(const nlohmann::json& in);
nlohmann::json compareFitsJson(const nlohmann::json& in);
nlohmann::json compareNonNestedJson(const nlohmann::json& in);
nlohmann::json responseSurfaceJson(const nlohmann::json& in);
nlohmann::json nullThresholdsJson(const nlohmann::json& in);
nlohmann::json bootstrapThresholdsJson(const nlohmann::json& in);

/// Human-readable summary: decision, Q0, candidate table, residual map.
void printDiagnosis(std::ostream& out, const Diagnosis& d);

}  // namespace paddy::doe
