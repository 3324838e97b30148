#include "measure/confidence_sequence.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <vector>

#include "measure/probability.h"

namespace raygate {
namespace {

void validate(double alpha_each_side) {
  require_open_interval(alpha_each_side, 0.0, 0.5, "confidence sequence: alpha per side");
}

// ln(e^a + e^b) without overflow.
double log_add(double a, double b) {
  const double high = std::max(a, b);
  return high + std::log1p(std::exp(std::min(a, b) - high));
}

// ln(2^(n+1) B(count + 1, n - count + 1)) = (n+1) ln 2 - ln(n+1) - ln C(n, count).
double log_scaled_beta(std::size_t n, std::size_t count) {
  return static_cast<double>(n + 1) * std::log(2.0) - std::log(static_cast<double>(n + 1)) -
         log_choose(n, count);
}

// The smallest count whose wealth reaches 1 / alpha, or n + 1 when none does. The binomial
// tail is summed upwards, so the scan costs O(k*) logarithms.
std::size_t scan_rejecting_count(std::size_t n, double alpha_each_side) {
  const double threshold = std::log(1.0 / alpha_each_side);
  const double log_half_power = -static_cast<double>(n + 1) * std::log(2.0);
  double log_cdf = log_half_power;          // P(Bin(n+1, 1/2) <= 0)
  double log_term = log_half_power;         // ln P(Bin(n+1, 1/2) = count)
  double log_beta = log_scaled_beta(n, 0);  // ln 2^(n+1) B(count + 1, n - count + 1)
  for (std::size_t count = 0; count <= n; ++count) {
    if (count > 0) {
      const auto c = static_cast<double>(count);
      const auto n1 = static_cast<double>(n + 1);
      log_term += std::log((n1 - c + 1.0) / c);  // C(n+1, c) / C(n+1, c-1)
      log_cdf = log_add(log_cdf, log_term);
      log_beta -= std::log((n1 - c) / c);  // C(n, c) / C(n, c-1)
    }
    if (log_beta + log_cdf >= threshold) return count;
  }
  return n + 1;
}

// k*(n) for every n asked so far, per alpha: a compare asks the same few levels after every
// round, and a simulation thousands of times, so each (alpha, n) is scanned once per thread.
// The table is a cache of a pure function; it changes no result.
std::size_t rejecting_count(std::size_t n, double alpha_each_side) {
  struct Table {
    double alpha = 0.0;
    std::vector<std::size_t> k_star;  // by n
  };
  thread_local std::vector<Table> tables;
  constexpr std::size_t kMaxTables = 64;    // distinct levels; more only in odd callers
  constexpr std::size_t kMaxRounds = 4096;  // beyond it, scan (no compare runs that long)
  if (n >= kMaxRounds) return scan_rejecting_count(n, alpha_each_side);
  auto table = std::find_if(tables.begin(), tables.end(),
                            [&](const Table& t) { return t.alpha == alpha_each_side; });
  if (table == tables.end()) {
    if (tables.size() >= kMaxTables) tables.clear();
    tables.push_back({alpha_each_side, {}});
    table = tables.end() - 1;
  }
  while (table->k_star.size() <= n) {
    table->k_star.push_back(scan_rejecting_count(table->k_star.size(), alpha_each_side));
  }
  return table->k_star[n];
}

}  // namespace

double median_sequence_log_wealth(std::size_t n, std::size_t count) {
  if (count > n) throw std::invalid_argument("confidence sequence: count above n");
  const double log_half_power = -static_cast<double>(n + 1) * std::log(2.0);
  double log_cdf = log_choose(n + 1, 0) + log_half_power;
  for (std::size_t j = 1; j <= count; ++j) {
    log_cdf = log_add(log_cdf, log_choose(n + 1, j) + log_half_power);
  }
  return log_scaled_beta(n, count) + log_cdf;
}

std::optional<Interval> median_sequence_interval(std::span<const double> values,
                                                 double alpha_each_side) {
  validate(alpha_each_side);
  const std::size_t n = values.size();
  // Testing "the median is below m" with count = #{x <= m}: m is rejected once its count
  // reaches k*, i.e. for m >= x(k*). The other side mirrors it: m < x(n + 1 - k*) is rejected.
  const std::size_t k_star = rejecting_count(n, alpha_each_side);
  if (n == 0 || k_star > n) return std::nullopt;
  std::vector<double> sorted(values.begin(), values.end());
  std::sort(sorted.begin(), sorted.end());
  return Interval{sorted[n - k_star], sorted[k_star - 1]};
}

std::size_t median_sequence_upper_rank(std::size_t n, double alpha_each_side) {
  validate(alpha_each_side);
  return rejecting_count(n, alpha_each_side);
}

std::size_t min_values_for_median_sequence(double alpha_each_side) {
  validate(alpha_each_side);
  // All n values on one side: wealth 2^(n+1)/(n+1) * (1 - 2^-(n+1)), which passes any
  // threshold; the cap only guards against a caller's absurd alpha (1e-300 needs about 1,010).
  const double threshold = std::log(1.0 / alpha_each_side);
  for (std::size_t n = 1; n < 100000; ++n) {
    if (median_sequence_log_wealth(n, n) >= threshold) return n;
  }
  throw std::invalid_argument("confidence sequence: alpha too small for any finite interval");
}

}  // namespace raygate
