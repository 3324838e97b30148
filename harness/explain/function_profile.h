// Where a run's simulated cost went, by function (issue 27): the self cost of every function in
// a cachegrind output file, read directly (not through cg_annotate). A cachegrind file lists
// "fl=FILE" and "fn=NAME" lines, each followed by lines "LINE COUNT..." in the order of its
// "events:" line; a line may leave trailing zero counts out. Every process of a run writes its
// own file (a wrapper's children too); a run's profile is their sum by function.
#pragma once

#include <filesystem>
#include <map>
#include <string>
#include <string_view>

#include "measure/simulated_cost.h"

namespace raygate {

struct FunctionCost {
  std::string name;  // demangled
  std::string file;  // the source file cachegrind attributed it to ("???" without debug info)
  SimulatedCounters self;
  // With its callees (callgrind only, explain/callgrind_profile.h; cachegrind records no calls).
  SimulatedCounters inclusive;
  bool inclusive_known = false;
};

// By demangled name: a function inlined or duplicated across files is one entry, so a change
// that only moves cost between its copies does not show as two changes.
using FunctionProfile = std::map<std::string, FunctionCost>;

// A symbol as people read it: "_ZN3foo3barEv" -> "foo::bar()"; anything that is not a mangled
// C++ name (valgrind demangles by default; C functions) is returned as it is.
std::string demangled(std::string_view symbol);

// Throws InfraError naming origin:line for a cost line before any fn=, a count that is not a
// number, more counts than events, or no "events:" line.
FunctionProfile parse_function_profile(std::string_view text, const std::string& origin);

// One profile file's text parsed (`origin` names it in errors).
using ProfileParser = FunctionProfile (*)(std::string_view text, const std::string& origin);
// The sum by function of every file in `dir` whose name starts with `prefix`, each read by
// `parse`; InfraError naming `tool` when there is none.
FunctionProfile sum_profile_files(const std::filesystem::path& dir, std::string_view prefix,
                                  std::string_view tool, ProfileParser parse);

// The sum of every cachegrind output file in `dir` (cg.*); InfraError when there is none.
FunctionProfile read_function_profiles(const std::filesystem::path& dir);

}  // namespace raygate
