// Experimental designs: factors, coded <-> real units, centre points, replicates, run order.
//
// Coding (Montgomery, Design and Analysis of Experiments, ch. 6 and 11; Design-Expert "coded
// factors"): x_coded = (x_real - m) / h with m = (low + high)/2 and h = (high - low)/2, so the
// low level is -1 and the high level +1. A Design stores the coded matrix; real values are
// derived from each Factor's low/high.
// Randomised run order: Fisher-Yates shuffle driven by std::mt19937_64(seed) with rejection
// sampling, so a given seed gives the same order with every standard library.
#pragma once
#include <Eigen/Dense>
#include <cstdint>
#include <string>
#include <vector>

namespace paddy::doe {

struct Factor {
  std::string name;
  double low = -1.0;   ///< real value at coded -1
  double high = 1.0;   ///< real value at coded +1
  double center() const { return 0.5 * (low + high); }
  double halfRange() const { return 0.5 * (high - low); }
  double toCoded(double real) const { return (real - center()) / halfRange(); }
  double toReal(double coded) const { return center() + coded * halfRange(); }
};

enum class PointType { Factorial, Axial, Edge, Center };
std::string pointTypeName(PointType t);

struct Design {
  std::vector<Factor> factors;
  Eigen::MatrixXd coded;          ///< runs x factors, coded units
  std::vector<PointType> type;    ///< one per run
  std::vector<int> stdOrder;      ///< 1-based standard order of each run
  int runs() const { return static_cast<int>(coded.rows()); }
  int k() const { return static_cast<int>(coded.cols()); }
  Eigen::MatrixXd real() const;   ///< runs x factors in real units
};

/// Factor letters as Design-Expert uses them: A, B, ..., H, J, ... (the letter I is skipped).
std::string factorLetter(int index);
/// k factors named A, B, C, ... coded -1..+1.
std::vector<Factor> defaultFactors(int k);

/// Build a design from a coded matrix (standard order 1..n).
Design makeDesign(std::vector<Factor> factors, Eigen::MatrixXd coded, std::vector<PointType> type);
/// Append n centre points (all factors at coded 0).
void addCenterPoints(Design& d, int n);
/// Each run repeated n times (n >= 1); the standard order of a copy is that of its original.
Design replicate(const Design& d, int n);
/// Reorder the runs randomly but reproducibly from the seed.
void randomize(Design& d, std::uint64_t seed);
/// Replace the factors (names, levels); the count must match.
void setFactors(Design& d, std::vector<Factor> factors);

Eigen::VectorXd toCoded(const std::vector<Factor>& f, const Eigen::VectorXd& real);
Eigen::VectorXd toReal(const std::vector<Factor>& f, const Eigen::VectorXd& coded);

}  // namespace paddy::doe
