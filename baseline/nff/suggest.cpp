// Keyword tables of the NFF reader and the "did you mean" for unknown keywords. NFF keywords
// are single letters, so people coming from other formats write `sphere` or `polygon`; those
// spelled-out names, wrong case and small typos all map back to the real keyword.
#include <algorithm>
#include <array>
#include <cctype>
#include <string>

#include "nff/reader.h"

namespace raygate::nff::detail {
namespace {

struct Entity {
  std::string_view keyword;
  std::string_view name;  // how messages call it
};

constexpr std::array<Entity, 8> kEntities{{{"v", "view (v)"},
                                           {"b", "background (b)"},
                                           {"l", "light (l)"},
                                           {"f", "fill material (f)"},
                                           {"c", "cone (c)"},
                                           {"s", "sphere (s)"},
                                           {"p", "polygon (p)"},
                                           {"pp", "patch (pp)"}}};

// Words people use for NFF entities, and the keyword each means.
struct Alias {
  std::string_view word;
  std::string_view keyword;
};

constexpr std::array<Alias, 14> kAliases{{{"view", "v"},
                                          {"camera", "v"},
                                          {"background", "b"},
                                          {"light", "l"},
                                          {"fill", "f"},
                                          {"material", "f"},
                                          {"cone", "c"},
                                          {"cylinder", "c"},
                                          {"sphere", "s"},
                                          {"polygon", "p"},
                                          {"poly", "p"},
                                          {"triangle", "p"},
                                          {"patch", "pp"},
                                          {"polypatch", "pp"}}};

std::string lower(std::string_view text) {
  std::string out(text);
  for (char& c : out) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return out;
}

// Edit distance counting a swap of two neighbours as one edit (optimal string alignment), so
// "angel" is one edit from "angle". Capped: tokens can be long garbage.
std::size_t edit_distance(std::string_view a, std::string_view b) {
  constexpr std::size_t kMax = 32;
  if (a.size() > kMax || b.size() > kMax) return 99;
  std::array<std::array<std::size_t, kMax + 1>, kMax + 1> d{};
  for (std::size_t i = 0; i <= a.size(); ++i) d[i][0] = i;
  for (std::size_t j = 0; j <= b.size(); ++j) d[0][j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t substitution = d[i - 1][j - 1] + (a[i - 1] == b[j - 1] ? 0 : 1);
      d[i][j] = std::min({d[i - 1][j] + 1, d[i][j - 1] + 1, substitution});
      if (i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1]) {
        d[i][j] = std::min(d[i][j], d[i - 2][j - 2] + 1);
      }
    }
  }
  return d[a.size()][b.size()];
}

// A word of 4 or more letters is "close" at distance 1, of 6 or more at distance 2; shorter
// words only match exactly (after lower-casing), or every short token would match something.
bool close_to(std::string_view word, std::string_view candidate) {
  const std::size_t distance = edit_distance(word, candidate);
  if (distance == 0) return true;
  if (candidate.size() >= 6) return distance <= 2;
  return candidate.size() >= 4 && distance <= 1;
}

std::string quoted_hint(std::string_view keyword) {
  return "; did you mean '" + std::string(keyword) + "'?";
}

}  // namespace

const char* const kViewKeywords[6] = {"from", "at", "up", "angle", "hither", "resolution"};

int view_keyword_index(std::string_view token) {
  for (int i = 0; i < 6; ++i) {
    if (token == kViewKeywords[i]) return i;
  }
  return -1;
}

std::string_view entity_name(std::string_view keyword) {
  for (const Entity& entity : kEntities) {
    if (entity.keyword == keyword) return entity.name;
  }
  return {};
}

std::string keyword_suggestion(std::string_view token, bool in_view) {
  const std::string word = lower(token);
  if (in_view) {
    for (const char* view_keyword : kViewKeywords) {
      if (close_to(word, view_keyword)) return quoted_hint(view_keyword);
    }
  }
  for (const Entity& entity : kEntities) {
    if (entity.keyword == word) return quoted_hint(entity.keyword);
  }
  for (const Alias& alias : kAliases) {
    if (close_to(word, alias.word)) return quoted_hint(alias.keyword);
  }
  for (const char* view_keyword : kViewKeywords) {
    if (word == view_keyword) return "; view keywords belong after a 'v'";
  }
  return {};
}

}  // namespace raygate::nff::detail
