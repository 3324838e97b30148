// shells (spd-spec.md §3.9): Pickover's sea shell, a logarithmic spiral of heavily overlapping
// spheres of growing size, meant as a pathological case. 1 light, no floor, no randomness.
#include <cmath>
#include <numbers>

#include "generators/generators.h"

namespace raygate::scenes {
namespace {

// The SPD's default spiral parameters (its -g, -a, -b, -e options are not exposed here).
constexpr double kGamma = 1.0;
constexpr double kAlpha = 0.0;
constexpr double kBeta = -2.0;
constexpr double kA = 0.15;
constexpr double kK = 1.0;

void write_header(NffWriter& out) {
  out.background({0.078, 0.361, 0.753});
  out.view({-6.0, -60.0, 35.0}, {0.0, 8.0, -15.0}, {0.0, 0.0, 1.0}, 45.0, 0.5, 512, 512);
  out.light({-100.0, -100.0, 100.0});
  out.material({{1.0, 0.8, 0.4}, 0.0, 0.8, 0.2, 0.5, 10.0, 0.0, 1.0});
}

}  // namespace

void generate_shells(int size, NffWriter& out) {
  write_header(out);
  // steps is a multiple of 3, so the integer divisions below are exact; the loop is inclusive
  // at both ends, hence 180·2^size + 1 spheres (the SPD header's count is off by one, §3.9).
  const long steps = static_cast<long>(180.0 * std::pow(2.0, size));
  for (long i = -(2 * steps) / 3; i <= steps / 3; ++i) {
    // Evaluated as ((3·6)·π·i)/steps: this order is part of the bytes (§3.9).
    const double theta =
        ((3 * 6) * std::numbers::pi * static_cast<double>(i)) / static_cast<double>(steps);
    const double rho = kK * std::exp(kA * theta);
    const double z = kAlpha > 0.0 ? kAlpha * theta : kBeta * rho;
    out.sphere({rho * std::sin(theta), rho * std::cos(theta), z}, rho / kGamma);
  }
}

}  // namespace raygate::scenes
