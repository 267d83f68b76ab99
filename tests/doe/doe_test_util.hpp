// Helpers shared by the doe tests.
#pragma once
#include <Eigen/Dense>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <random>
#include <string>

namespace doe_test {

// n independent standard normal draws.
inline Eigen::VectorXd gaussian(std::mt19937_64& rng, Eigen::Index n) {
  std::normal_distribution<double> N;
  Eigen::VectorXd v(n);
  for (Eigen::Index i = 0; i < n; ++i) v(i) = N(rng);
  return v;
}

inline std::string referenceDir() {
  // PADDY_SOURCE_DIR from the test environment, else the source tree this test was built from.
  const char* src = std::getenv("PADDY_SOURCE_DIR");
  return std::string(src && *src ? src : PADDY_DOE_TEST_SOURCE_DIR) + "/../shared/reference/";
}

inline std::filesystem::path tempDir(const std::string& tag) {
  std::random_device rd;
  auto p = std::filesystem::temp_directory_path() / ("paddy_doe_" + tag + "_" + std::to_string(rd()));
  std::filesystem::create_directories(p);
  return p;
}

// Half a unit of the last printed decimal.
inline double printedHalfUnit(const std::string& printed) {
  const auto dot = printed.find('.');
  const int decimals = dot == std::string::npos ? 0 : static_cast<int>(printed.size() - dot - 1);
  double tol = 0.5;
  for (int i = 0; i < decimals; ++i) tol /= 10.0;
  return tol;
}

// |value - printed| within half a unit of the printed number's last decimal.
inline bool matchesPrinted(double value, const std::string& printed) {
  return std::abs(value - std::stod(printed)) <= printedHalfUnit(printed) * (1.0 + 1e-9);
}

}  // namespace doe_test
