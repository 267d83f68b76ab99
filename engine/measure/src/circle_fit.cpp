// Least-squares circle fits: Kåsa (algebraic) and geometric (Levenberg–Marquardt).
// Formulas and sources in paddy/measure/circle_fit.hpp.
#include <paddy/errors.hpp>
#include <paddy/measure/circle_fit.hpp>

#include <Eigen/Dense>

#include <cmath>
#include <numbers>

namespace paddy::measure {

namespace {

void checkPoints(const std::vector<Vec2>& pts, const char* what) {
  if (pts.size() < 3)
    throw InputError(std::string(what) + ": a circle needs at least 3 points, got " + std::to_string(pts.size()));
  for (std::size_t i = 0; i < pts.size(); ++i)
    if (!pts[i].allFinite()) throw InputError(std::string(what) + ": point " + std::to_string(i) + " is not finite");
}

double rmsResidual(const std::vector<Vec2>& pts, const Vec2& c, double r) {
  double s = 0.0;
  for (const auto& p : pts) {
    const double e = (p - c).norm() - r;
    s += e * e;
  }
  return std::sqrt(s / static_cast<double>(pts.size()));
}

}  // namespace

CircleFit fitCircleKasa(const std::vector<Vec2>& pts) {
  checkPoints(pts, "fitCircleKasa");
  // Work relative to the mean and in units of the spread, for conditioning.
  Vec2 mean = Vec2::Zero();
  for (const auto& p : pts) mean += p;
  mean /= static_cast<double>(pts.size());
  double scale = 0.0;
  for (const auto& p : pts) scale = std::max(scale, (p - mean).norm());
  if (!(scale > 0.0)) throw InputError("fitCircleKasa: all points coincide");
  // Normal equations of the 3-parameter linear problem (well conditioned after centring and
  // scaling; fixed 3x3 sizes).
  Eigen::Matrix3d M = Eigen::Matrix3d::Zero();
  Eigen::Vector3d rhs = Eigen::Vector3d::Zero();
  for (const auto& p : pts) {
    const Vec2 q = (p - mean) / scale;
    const Eigen::Vector3d a(q.x(), q.y(), 1.0);
    M += a * a.transpose();
    rhs -= a * q.squaredNorm();
  }
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig;
  eig.computeDirect(M, Eigen::EigenvaluesOnly);
  if (!(eig.eigenvalues()(0) > 1e-12 * eig.eigenvalues()(2)))
    throw InputError("fitCircleKasa: the points are collinear; no circle fits them");
  const Eigen::Vector3d s = M.inverse() * rhs;  // closed-form 3x3 inverse
  const Vec2 c(-0.5 * s(0), -0.5 * s(1));
  const double r2 = c.squaredNorm() - s(2);
  if (!(r2 > 0.0) || !std::isfinite(r2)) throw InputError("fitCircleKasa: degenerate point set; no circle fits it");
  CircleFit f;
  f.centre = mean + scale * c;
  f.radius = scale * std::sqrt(r2);
  f.rms = rmsResidual(pts, f.centre, f.radius);
  return f;
}

CircleFit fitCircle(const std::vector<Vec2>& pts, int max_iterations) {
  CircleFit f = fitCircleKasa(pts);
  Eigen::Vector3d x(f.centre.x(), f.centre.y(), f.radius);
  auto cost = [&](const Eigen::Vector3d& v) {
    double s = 0.0;
    for (const auto& p : pts) {
      const double e = (p - v.head<2>()).norm() - v(2);
      s += e * e;
    }
    return s;
  };
  double c0 = cost(x);
  double lambda = 1e-3;
  f.converged = false;
  int it = 0;
  for (; it < max_iterations; ++it) {
    Eigen::Matrix3d JtJ = Eigen::Matrix3d::Zero();
    Eigen::Vector3d Jtr = Eigen::Vector3d::Zero();
    for (const auto& p : pts) {
      const Vec2 d = p - x.head<2>();
      const double dist = std::max(d.norm(), 1e-300);
      const Eigen::Vector3d J(-d.x() / dist, -d.y() / dist, -1.0);
      const double e = dist - x(2);
      JtJ += J * J.transpose();
      Jtr += J * e;
    }
    bool improved = false;
    for (int tries = 0; tries < 30 && !improved; ++tries) {
      Eigen::Matrix3d M = JtJ;
      M.diagonal() *= (1.0 + lambda);
      const Eigen::Vector3d step = M.ldlt().solve(-Jtr);
      const Eigen::Vector3d xn = x + step;
      const double cn = cost(xn);
      if (std::isfinite(cn) && cn <= c0) {
        const double rel = step.norm() / std::max(x.norm(), 1e-300);
        x = xn;
        const double dc = c0 - cn;
        c0 = cn;
        lambda = std::max(lambda * 0.1, 1e-12);
        improved = true;
        if (rel < 1e-13 || dc <= 1e-15 * std::max(cn, 1e-300)) f.converged = true;
      } else {
        lambda *= 10.0;
      }
    }
    if (!improved) {  // no descent left: at the minimum within round-off
      f.converged = true;
      break;
    }
    if (f.converged) {
      ++it;
      break;
    }
  }
  f.centre = x.head<2>();
  f.radius = std::abs(x(2));
  f.iterations = it;
  f.rms = rmsResidual(pts, f.centre, f.radius);
  return f;
}

std::vector<Vec2> circlePoints(const CircleFit& c, int n) {
  if (n < 3) throw InputError("circlePoints: need at least 3 points, got " + std::to_string(n));
  std::vector<Vec2> pts(static_cast<std::size_t>(n) + 1);
  for (int k = 0; k <= n; ++k) {
    const double t = 2.0 * std::numbers::pi * k / n;
    pts[static_cast<std::size_t>(k)] = c.centre + c.radius * Vec2(std::cos(t), std::sin(t));
  }
  return pts;
}

}  // namespace paddy::measure
