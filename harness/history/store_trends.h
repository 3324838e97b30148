// The trend beside a new document: each of its scenes' normalized ratio over the last commits in
// the results store, within the scene's own series, for the reports' trend plots.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "report/reporter.h"
#include "results/results.h"

namespace raygate {

struct StoreTrends {
  std::vector<TrendSeries> trends;  // scenes with at least two measured commits, oldest first
  std::string warning;              // why there are none although a store was named; "" if fine
};

// The normalized ratio of each of the document's scenes over `commits` commits in the store
// (oldest first) ending at the newest of the document's own commits (its base and head, or the
// tracer; widened to reach both), within the scene's series (results/series.h: the same
// repository, adapter and measurement, suite, scene settings, timing and baseline). No store, or none yet: no trends and no
// warning; a store that cannot be read: no trends and a warning (a report is still written).
StoreTrends trends_from_store(const std::filesystem::path& store, const ResultsDocument& document,
                              std::size_t commits = 20);

}  // namespace raygate
