// Central composite designs (Box & Wilson 1951; Montgomery, Design and Analysis of Experiments,
// ch. 11; Design-Expert CCD options).
//
// 2^k factorial cube (or a 2^(k-p) fraction), 2k axial points at +-alpha on each axis, and centre
// points. alpha = (n_F)^(1/4) makes the design rotatable (n_F = factorial runs).
//   Circumscribed (CCC): cube at +-1, axial at +-alpha.
//   Inscribed (CCI):     the CCC scaled by 1/alpha, so axial points sit at +-1.
//   Face-centred (CCF):  alpha = 1.
#pragma once
#include "paddy/doe/design.hpp"

#include <optional>
#include <string>
#include <vector>

namespace paddy::doe {

enum class CcdType { Circumscribed, Inscribed, FaceCentred };

struct CcdOptions {
  CcdType type = CcdType::Circumscribed;
  std::optional<double> alpha;           ///< default: rotatable (n_F^(1/4))
  int centerPoints = 0;
  std::vector<std::string> generators;   ///< optional fractional cube, e.g. {"E=ABCD"}
};

double rotatableAlpha(int factorialRuns);
Design centralComposite(int k, const CcdOptions& opt = {});

}  // namespace paddy::doe
