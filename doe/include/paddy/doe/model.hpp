// Polynomial response-surface models in coded factors (Montgomery, Design and Analysis of
// Experiments, ch. 11; Design-Expert model names).
//
// A term is a product of coded factors with integer powers, prod_j x_j^(e_j); the intercept has
// all powers 0. Term names: "Intercept", "A", "A:B", "A^2", "A:B:C", "A^2:B" using the factor names.
//   linear    : Intercept + main effects
//   2fi       : linear + all two-factor interactions
//   quadratic : 2fi + pure squares
//   linear+curvature: linear model plus a centre-point indicator column (see anova.hpp)
// Explicit lists are parsed from "A, B, A:B, A^2" (or '+' separated).
#pragma once
#include <Eigen/Dense>
#include <string>
#include <vector>

namespace paddy::doe {

struct Term {
  std::vector<int> powers;  ///< one exponent per factor
  int degree() const;
  bool isIntercept() const { return degree() == 0; }
  bool operator==(const Term&) const = default;
};

enum class ModelKind { Linear, LinearCurvature, TwoFI, Quadratic, Custom };
ModelKind parseModelKind(const std::string& s);  ///< "linear", "linear+curvature", "2fi", "quadratic"
std::string modelKindName(ModelKind k);

struct Model {
  std::vector<std::string> factorNames;
  std::vector<Term> terms;

  static Model linear(std::vector<std::string> names);
  static Model twoFI(std::vector<std::string> names);
  static Model quadratic(std::vector<std::string> names);
  static Model make(ModelKind kind, std::vector<std::string> names);
  /// Explicit term list; throws DoeError naming an unknown factor.
  static Model parse(std::vector<std::string> names, const std::string& spec, bool intercept = true);

  int k() const { return static_cast<int>(factorNames.size()); }
  int p() const { return static_cast<int>(terms.size()); }
  std::string termName(int i) const;
  std::vector<std::string> termNames() const;
  bool hasIntercept() const;
  /// Model matrix (runs x terms) for coded factor settings (runs x k).
  Eigen::MatrixXd matrix(const Eigen::MatrixXd& coded) const;
  Eigen::RowVectorXd row(const Eigen::VectorXd& coded) const;
  double predict(const Eigen::VectorXd& beta, const Eigen::VectorXd& coded) const;
};

/// Coefficients of the same polynomial in real units: expands each coded term
/// prod ((x_j - m_j)/h_j)^e_j. Returns (monomial term, coefficient) pairs, intercept first.
struct ActualTerm {
  Term term;
  double coefficient;
};
std::vector<ActualTerm> actualCoefficients(const Model& m, const Eigen::VectorXd& beta,
                                           const Eigen::VectorXd& centers,
                                           const Eigen::VectorXd& halfRanges);

}  // namespace paddy::doe
