// Two additions to every report (issue 27), kept in one place so each reporter only calls
// them: the peak memory of each scene (head against base with its verdict, or a run's peak),
// and where a REGRESSED scene's time went (explain/explanation.h): top 5 functions on the
// terminal, top 10 in Markdown, a table in HTML, everything in JSON.
#pragma once

#include <nlohmann/json.hpp>
#include <string>

#include "report/reporter.h"

namespace raygate::report {

inline constexpr std::size_t kConsoleExplained = 5;
inline constexpr std::size_t kMarkdownExplained = 10;

// Plain text for the terminal ("" when there is nothing to say): the memory table, then each
// explained scene's top functions.
std::string memory_console(const ReportInput& input);
std::string explanation_console(const ReportInput& input);

// Markdown blocks, each starting with a blank line; "" when there is nothing to say.
std::string memory_markdown(const ReportInput& input);
std::string explanation_markdown(const ReportInput& input);

// An HTML <section> (cards like the others); "" when there is nothing to say.
std::string memory_html(const ReportInput& input);
std::string explanation_html(const ReportInput& input);

// The scene's "memory" object for the JSON report: peaks in KiB, change, verdict, limit;
// null when the scene has no own peaks.
nlohmann::json memory_json(const ReportInput& input, const SceneResult& scene);

}  // namespace raygate::report
