// Ordinary least squares in log-log, a quadratic term to see curvature, and a fixed-cost model
// t = a + b·n^k for the common way a power law fails on run times: start-up (parsing, process
// creation, building an acceleration structure's fixed part) that does not grow with n.
#include "scaling/power_fit.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "scaling/fit_limits.h"

namespace raygate {
namespace {

// Local exponents at the two ends that differ by more than this describe a curve, not a line,
// whatever the noise: a quarter of a power over the range changes projections by factors.
constexpr double kSlopeChangeAlways = 0.5;
// ... and by more than this, when the quadratic term is also significant.
constexpr double kSlopeChangeSignificant = 0.2;

struct Line {
  double slope = 0.0;
  double intercept = 0.0;
  double residual_ss = 0.0;
  double total_ss = 0.0;
  double sxx = 0.0;
};

Line fit_line(std::span<const double> x, std::span<const double> y) {
  const double n = static_cast<double>(x.size());
  double mx = 0, my = 0;
  for (std::size_t i = 0; i < x.size(); ++i) mx += x[i], my += y[i];
  mx /= n, my /= n;
  Line line;
  double sxy = 0;
  for (std::size_t i = 0; i < x.size(); ++i) {
    line.sxx += (x[i] - mx) * (x[i] - mx);
    sxy += (x[i] - mx) * (y[i] - my);
    line.total_ss += (y[i] - my) * (y[i] - my);
  }
  line.slope = line.sxx > 0 ? sxy / line.sxx : 0.0;
  line.intercept = my - line.slope * mx;
  for (std::size_t i = 0; i < x.size(); ++i) {
    const double r = y[i] - (line.intercept + line.slope * x[i]);
    line.residual_ss += r * r;
  }
  return line;
}

double determinant(const std::array<std::array<double, 3>, 3>& m) {
  return m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) -
         m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
         m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
}

// t statistic of the quadratic coefficient of y = a + b·x + c·x², x centred; 0 when it cannot be
// computed (fewer than 4 points, a singular design, an exact fit gives a huge t instead).
struct Curvature {
  double coefficient = 0.0;
  double t = 0.0;
};

Curvature fit_curvature(std::span<const double> x, std::span<const double> y) {
  const std::size_t n = x.size();
  if (n < 4) return {};
  double mx = 0;
  for (const double v : x) mx += v;
  mx /= static_cast<double>(n);
  std::array<std::array<double, 3>, 3> xtx{};
  std::array<double, 3> xty{};
  for (std::size_t i = 0; i < n; ++i) {
    const double u = x[i] - mx;
    const std::array<double, 3> row{1.0, u, u * u};
    for (int r = 0; r < 3; ++r) {
      xty[r] += row[r] * y[i];
      for (int c = 0; c < 3; ++c) xtx[r][c] += row[r] * row[c];
    }
  }
  const double det = determinant(xtx);
  if (std::abs(det) < 1e-12) return {};
  std::array<std::array<double, 3>, 3> with_y = xtx;
  for (int r = 0; r < 3; ++r) with_y[r][2] = xty[r];
  const std::array<double, 3> beta_c{0, 0, determinant(with_y) / det};  // Cramer for c only
  // a and b for the residuals, from the first two normal equations given c.
  const double a_b_det = xtx[0][0] * xtx[1][1] - xtx[0][1] * xtx[1][0];
  const double r0 = xty[0] - xtx[0][2] * beta_c[2], r1 = xty[1] - xtx[1][2] * beta_c[2];
  const double a = (r0 * xtx[1][1] - xtx[0][1] * r1) / a_b_det;
  const double b = (xtx[0][0] * r1 - xtx[1][0] * r0) / a_b_det;
  double ss = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const double u = x[i] - mx;
    const double r = y[i] - (a + b * u + beta_c[2] * u * u);
    ss += r * r;
  }
  // Var(c) = s² · [(XᵀX)⁻¹]₂₂, the cofactor of the corner over the determinant.
  const double cofactor = xtx[0][0] * xtx[1][1] - xtx[0][1] * xtx[1][0];
  const double s2 = ss / static_cast<double>(n - 3);
  const double se = std::sqrt(s2 * cofactor / det);
  return {beta_c[2], se > 0 ? beta_c[2] / se : 1e9};
}

// Sum of squared ln-residuals of t = a + b·n^k. For each a, b and k come from a weighted line
// through ln(t - a): weights ((t - a)/t)² turn an error in ln(t - a) into the error in ln t it
// causes, so the sizes where t - a is tiny (all start-up) do not decide the slope.
struct FixedCostFit {
  double a = 0.0;
  double k = 0.0;
  double ss = INFINITY;
};

FixedCostFit fixed_cost_at(double a, std::span<const double> x, std::span<const double> t,
                           std::span<const double> y) {
  double sw = 0, sx = 0, sy = 0;
  std::vector<double> u(t.size()), w(t.size());
  for (std::size_t i = 0; i < t.size(); ++i) {
    u[i] = std::log(t[i] - a);
    w[i] = (t[i] - a) / t[i] * (t[i] - a) / t[i];
    sw += w[i], sx += w[i] * x[i], sy += w[i] * u[i];
  }
  const double mx = sx / sw, mu = sy / sw;
  double sxx = 0, sxu = 0;
  for (std::size_t i = 0; i < t.size(); ++i) {
    sxx += w[i] * (x[i] - mx) * (x[i] - mx);
    sxu += w[i] * (x[i] - mx) * (u[i] - mu);
  }
  const double k = sxx > 0 ? sxu / sxx : 0.0;
  const double c = mu - k * mx;
  double ss = 0;
  for (std::size_t i = 0; i < t.size(); ++i) {
    const double r = y[i] - std::log(a + std::exp(c + k * x[i]));
    ss += r * r;
  }
  return {a, k, ss};
}

FixedCostFit fit_fixed_cost(std::span<const double> x, std::span<const double> t,
                            std::span<const double> y) {
  const double smallest = *std::min_element(t.begin(), t.end());
  FixedCostFit best;
  // A coarse scan of a over [0, smallest), then a fine one around the best step.
  constexpr int kSteps = 400;
  double lo = 0.0, hi = smallest * (1 - 1e-9);
  for (int pass = 0; pass < 2; ++pass) {
    const double step = (hi - lo) / kSteps;
    for (int i = 0; i < kSteps; ++i) {
      const FixedCostFit candidate = fixed_cost_at(lo + step * i, x, t, y);
      if (candidate.ss < best.ss) best = candidate;
    }
    lo = std::max(0.0, best.a - step);
    hi = std::min(smallest * (1 - 1e-9), best.a + step);
  }
  return best;
}

void diagnose(PowerFit& fit, std::span<const double> x, std::span<const double> y,
              const Line& line) {
  const std::size_t n = x.size();
  fit.small_end_exponent = fit_line(x.first(3), y.first(3)).slope;
  fit.large_end_exponent = fit_line(x.last(3), y.last(3)).slope;
  fit.growth_exponent = fit.exponent;
  const double change = fit.large_end_exponent - fit.small_end_exponent;
  const Curvature curvature = fit_curvature(x, y);
  const bool significant = n >= 4 && std::abs(curvature.t) > student_t_975(static_cast<int>(n) - 3);
  const bool curved = std::abs(change) > kSlopeChangeAlways ||
                      (significant && std::abs(change) > kSlopeChangeSignificant);
  if (curved && change > 0) {
    std::vector<double> t(n);
    for (std::size_t i = 0; i < n; ++i) t[i] = std::exp(y[i]);
    const FixedCostFit fixed = fit_fixed_cost(x, t, y);
    if (fixed.a > 0 && fixed.ss < line.residual_ss) {
      fit.quality = FitQuality::startup_dominated;
      fit.fixed_cost = fixed.a;
      fit.growth_exponent = fixed.k;
      return;
    }
  }
  if (curved) {
    fit.quality = FitQuality::curved;
  } else if (std::sqrt(line.residual_ss / static_cast<double>(n - 2)) > kScatterLimit) {
    fit.quality = FitQuality::scattered;
  } else {
    fit.quality = FitQuality::power_law;
  }
}

}  // namespace

double student_t_975(int dof) {
  if (dof < 1) throw std::invalid_argument("student_t_975: dof must be >= 1");
  // Tabulated quantiles for small dof, where series expansions are poor.
  static constexpr std::array<double, 30> kTable{
      12.7062, 4.3027, 3.1824, 2.7764, 2.5706, 2.4469, 2.3646, 2.3060, 2.2622, 2.2281,
      2.2010,  2.1788, 2.1604, 2.1448, 2.1314, 2.1199, 2.1098, 2.1009, 2.0930, 2.0860,
      2.0796,  2.0739, 2.0687, 2.0639, 2.0595, 2.0555, 2.0518, 2.0484, 2.0452, 2.0423};
  if (dof <= 30) return kTable[static_cast<std::size_t>(dof - 1)];
  // Cornish-Fisher expansion around the normal quantile, accurate to 1e-4 beyond 30 dof.
  const double z = 1.959964, v = dof;
  return z + (z * z * z + z) / (4 * v) +
         (5 * std::pow(z, 5) + 16 * z * z * z + 3 * z) / (96 * v * v);
}

PowerFit fit_power_law(std::span<const SizePoint> points) {
  std::vector<SizePoint> sorted(points.begin(), points.end());
  for (const SizePoint& p : sorted) {
    if (!(p.primitives > 0) || !std::isfinite(p.primitives) || !(p.value > 0) ||
        !std::isfinite(p.value)) {
      throw std::invalid_argument("fit_power_law: primitives and value must be positive, got " +
                                  std::to_string(p.primitives) + " and " + std::to_string(p.value));
    }
  }
  std::sort(sorted.begin(), sorted.end(),
            [](const SizePoint& a, const SizePoint& b) { return a.primitives < b.primitives; });
  std::vector<double> x, y;
  for (const SizePoint& p : sorted)
    x.push_back(std::log(p.primitives)), y.push_back(std::log(p.value));
  PowerFit fit;
  fit.points = static_cast<int>(sorted.size());
  if (sorted.size() < 2 || x.front() == x.back()) {
    if (!sorted.empty()) fit.log_prefactor = y.front();
    return fit;
  }
  const Line line = fit_line(x, y);
  fit.exponent = line.slope;
  fit.log_prefactor = line.intercept;
  fit.r_squared = line.total_ss > 0 ? 1 - line.residual_ss / line.total_ss : 1.0;
  fit.growth_exponent = fit.exponent;
  if (sorted.size() < 3) {
    fit.exponent_interval = {fit.exponent, fit.exponent};
    return fit;
  }
  const double se = std::sqrt(line.residual_ss / static_cast<double>(sorted.size() - 2) / line.sxx);
  const double half = student_t_975(fit.points - 2) * se;
  fit.exponent_interval = {fit.exponent - half, fit.exponent + half};
  diagnose(fit, x, y, line);
  return fit;
}

}  // namespace raygate
