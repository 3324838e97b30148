// Mann-Whitney U test (Wilcoxon rank-sum), two-sided, by the normal approximation with the tie
// correction of the variance and a continuity correction (as R's wilcox.test(exact = FALSE,
// correct = TRUE)). It compares two sets of per-round normalized ratios without assuming a
// distribution; raygate reports it beside the bootstrap CI as a second, pairing-free opinion.
#pragma once

#include <span>

namespace raygate {

struct MannWhitneyResult {
  // Pairs (a_i, b_j) with a_i > b_j, ties counting 1/2; equals R_a - n_a (n_a + 1) / 2 with
  // midranks. Ranges over [0, n_a n_b]; above n_a n_b / 2 means `a` tends to be larger.
  double u = 0.0;
  double z = 0.0;        // signed, after continuity correction; 0 when every value ties
  double p_value = 1.0;  // two-sided
};

// Throws std::invalid_argument if either sample is empty. With fewer than about 8 values per side
// the normal approximation is rough (p is then only indicative); no exact test is done.
MannWhitneyResult mann_whitney_u(std::span<const double> a, std::span<const double> b);

}  // namespace raygate
