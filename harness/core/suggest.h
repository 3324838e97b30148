// "Did you mean" for files people write (adapters, policies, suites, results documents read by
// core/json_field.h): the closest known word to a misspelt key or placeholder. A typo should
// cost the user one glance, not a trip to the README.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace raygate {

// Optimal-string-alignment distance: Levenshtein plus adjacent transpositions, because the most
// common typo ("tiemout") swaps two letters and should count as one edit, not two.
int edit_distance(std::string_view a, std::string_view b);

// The candidate closest to `word`, if it is close enough to be a plausible typo (at most two
// edits, or a third of the word's length for long words). Ties go to the earlier candidate.
std::optional<std::string> closest_match(std::string_view word,
                                         const std::vector<std::string>& candidates);

}  // namespace raygate
