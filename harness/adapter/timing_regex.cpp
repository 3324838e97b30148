#include "adapter/timing_regex.h"

#define PCRE2_CODE_UNIT_WIDTH 8
#include <pcre2.h>

#include <fmt/core.h>

namespace raygate {
namespace {

std::string pcre2_message(int code) {
  PCRE2_UCHAR buffer[256];
  const int length = pcre2_get_error_message(code, buffer, sizeof buffer);
  if (length < 0) return "error " + std::to_string(code);
  return std::string(reinterpret_cast<const char*>(buffer), static_cast<std::size_t>(length));
}

// The heap PCRE2 may use for one match's backtracking, in KiB (its default is 20 GB).
constexpr unsigned kHeapLimitKib = 20000;

}  // namespace

struct TimingRegex::Handles {
  pcre2_code* code = nullptr;
  pcre2_match_context* context = nullptr;
  pcre2_match_data* data = nullptr;
  ~Handles() {
    pcre2_match_data_free(data);
    pcre2_match_context_free(context);
    pcre2_code_free(code);
  }
};

TimingRegex::TimingRegex(const std::string& pattern) : handles_(std::make_unique<Handles>()) {
  int error = 0;
  PCRE2_SIZE offset = 0;
  handles_->code = pcre2_compile(reinterpret_cast<PCRE2_SPTR>(pattern.data()), pattern.size(), 0,
                                 &error, &offset, nullptr);
  if (handles_->code == nullptr) {
    throw std::invalid_argument(
        fmt::format("does not compile: {} at character {}", pcre2_message(error), offset + 1));
  }
  handles_->context = pcre2_match_context_create(nullptr);
  handles_->data = pcre2_match_data_create_from_pattern(handles_->code, nullptr);
  if (handles_->context == nullptr || handles_->data == nullptr) throw std::bad_alloc();
  pcre2_set_match_limit(handles_->context, kMatchLimit);
  pcre2_set_depth_limit(handles_->context, kMatchLimit);
  pcre2_set_heap_limit(handles_->context, kHeapLimitKib);
}

TimingRegex::~TimingRegex() = default;

std::size_t TimingRegex::capture_groups() const {
  std::uint32_t count = 0;
  pcre2_pattern_info(handles_->code, PCRE2_INFO_CAPTURECOUNT, &count);
  return count;
}

std::optional<std::optional<std::string_view>> TimingRegex::first_group(
    std::string_view line) const {
  const int found = pcre2_match(handles_->code, reinterpret_cast<PCRE2_SPTR>(line.data()),
                                line.size(), 0, 0, handles_->data, handles_->context);
  if (found == PCRE2_ERROR_NOMATCH) return std::nullopt;
  if (found < 0) {
    throw RegexTooCostly(fmt::format(
        "timing.regex stopped on a line of the tracer's output: {} (more than {} steps of "
        "backtracking; a repeated group that itself repeats, such as (a+)+, can take "
        "exponential time: write the pattern without one)",
        pcre2_message(found), kMatchLimit));
  }
  const PCRE2_SIZE* span = pcre2_get_ovector_pointer(handles_->data);
  if (found < 2 || span[2] == PCRE2_UNSET) return std::optional<std::string_view>{};
  return std::optional<std::string_view>{line.substr(span[2], span[3] - span[2])};
}

}  // namespace raygate
