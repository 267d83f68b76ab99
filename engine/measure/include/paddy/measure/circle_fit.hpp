// Least-squares circle fit to 2-D points.
//   Kåsa (algebraic) fit: minimise Σ (x² + y² + B x + C y + E)² — linear; centre (−B/2, −C/2),
//     radius sqrt(B²/4 + C²/4 − E) (Kåsa 1976, IEEE Trans. Instrum. Meas. IM-25:8).
//   Geometric fit: minimise Σ (|p_i − c| − R)² by Levenberg–Marquardt from the Kåsa start
//     (Chernov 2010, "Circular and Linear Regression", ch. 4; Gander, Golub & Strebel 1994).
// The Kåsa fit is biased toward smaller circles for arcs; on full noisy circles both agree.
#pragma once

#include <paddy/measure/common.hpp>

#include <vector>

namespace paddy::measure {

struct CircleFit {
  Vec2 centre = Vec2::Zero();  // [m]
  double radius = 0.0;         // [m]
  double rms = 0.0;            // sqrt(mean (|p_i − c| − R)²) [m]
  int iterations = 0;          // LM iterations (0 for the Kåsa fit)
  bool converged = true;
  double diameter() const { return 2.0 * radius; }
};

// Throws InputError for fewer than 3 points, non-finite points or (nearly) collinear points.
CircleFit fitCircleKasa(const std::vector<Vec2>& points);
CircleFit fitCircle(const std::vector<Vec2>& points, int max_iterations = 100);

// n + 1 points around the circle (closed: the last repeats the first), for pictures.
std::vector<Vec2> circlePoints(const CircleFit& circle, int n = 360);

}  // namespace paddy::measure
