#include "compare/image_verdict.h"

#include "core/enum_words.h"

namespace raygate {
namespace {

// Each verdict's word, spelt once for documents, database rows and printed text.
constexpr EnumWords<ImageVerdict, 6> kVerdictWords{{{ImageVerdict::missing, "missing"},
                                                    {ImageVerdict::pass, "pass"},
                                                    {ImageVerdict::warn, "warn"},
                                                    {ImageVerdict::inconclusive, "inconclusive"},
                                                    {ImageVerdict::error, "error"},
                                                    {ImageVerdict::fail, "fail"}}};

}  // namespace

std::string_view to_string(ImageVerdict verdict) {
  return word_of(kVerdictWords, verdict, "error");
}

std::optional<ImageVerdict> parse_image_verdict(std::string_view text) {
  return value_of(kVerdictWords, text);
}

}  // namespace raygate
