#include "adapter/placeholders.h"

#include <algorithm>
#include <array>
#include <stdexcept>
#include <utility>

#include "core/suggest.h"

namespace raygate {
namespace {

using Member = std::optional<std::string> Placeholders::*;

constexpr std::array<std::pair<std::string_view, Member>, 13> kMembers{{
    {"src", &Placeholders::src},
    {"repo_root", &Placeholders::repo_root},
    {"build", &Placeholders::build},
    {"jobs", &Placeholders::jobs},
    {"threads", &Placeholders::threads},
    {"scene", &Placeholders::scene},
    {"image", &Placeholders::image},
    {"workdir", &Placeholders::workdir},
    {"raygate_source", &Placeholders::raygate_source},
    {"scene_stem", &Placeholders::scene_stem},
    {"width", &Placeholders::width},
    {"height", &Placeholders::height},
    {"seed", &Placeholders::seed},
}};

// One piece of a template: literal text, or a placeholder name (without braces).
struct Piece {
  bool is_placeholder = false;
  std::string text;
};

struct Parsed {
  std::vector<Piece> pieces;
  std::optional<std::string> error;
};

// Splits a template the way fmt does: "{{"/"}}" are literal braces, "{name}" a placeholder,
// any other brace an error (so a forgotten brace is caught, not passed to the tracer).
Parsed parse(std::string_view text) {
  Parsed out;
  std::string literal;
  for (std::size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    const bool doubled = i + 1 < text.size() && text[i + 1] == c;
    if ((c == '{' || c == '}') && doubled) {
      literal += c;
      ++i;
    } else if (c == '}') {
      out.error = "unmatched '}' (write '}}' for a literal brace)";
      return out;
    } else if (c == '{') {
      const std::size_t close = text.find('}', i + 1);
      if (close == std::string_view::npos) {
        out.error = "unmatched '{' (write '{{' for a literal brace)";
        return out;
      }
      if (!literal.empty()) out.pieces.push_back({false, std::move(literal)});
      literal.clear();
      out.pieces.push_back({true, std::string(text.substr(i + 1, close - i - 1))});
      i = close;
    } else {
      literal += c;
    }
  }
  if (!literal.empty()) out.pieces.push_back({false, std::move(literal)});
  return out;
}

std::string braced(std::string_view name) {
  std::string out(1, '{');
  out += name;
  out += '}';
  return out;
}

std::string braced_list(const std::vector<std::string>& names) {
  std::string out;
  for (const std::string& n : names) out += (out.empty() ? "" : ", ") + braced(n);
  return out;
}

bool contains(const std::vector<std::string>& names, std::string_view name) {
  return std::find(names.begin(), names.end(), name) != names.end();
}

std::string field_words(TemplateField field) {
  return field == TemplateField::build ? "build steps" : "run settings";
}

}  // namespace

const std::optional<std::string>* Placeholders::find(std::string_view name) const {
  for (const auto& [member_name, member] : kMembers) {
    if (member_name == name) return &(this->*member);
  }
  return nullptr;
}

const std::vector<std::string>& placeholder_names() {
  static const std::vector<std::string> names = [] {
    std::vector<std::string> out;
    for (const auto& entry : kMembers) out.emplace_back(entry.first);
    return out;
  }();
  return names;
}

const std::vector<std::string>& placeholders_allowed_in(TemplateField field) {
  // Build steps run once per commit: no scene, image, run directory or thread count yet.
  static const std::vector<std::string> build{"src", "repo_root", "build", "jobs",
                                              "raygate_source"};
  // Runs happen per scene; {jobs} is a build setting, {threads} is its run-time counterpart.
  static const std::vector<std::string> run{"src",        "repo_root", "build",   "threads",
                                            "scene",      "image",     "workdir", "raygate_source",
                                            "scene_stem", "width",     "height",  "seed"};
  return field == TemplateField::build ? build : run;
}

std::optional<std::string> template_error(std::string_view text, TemplateField field) {
  const Parsed parsed = parse(text);
  if (parsed.error) return parsed.error;
  for (const Piece& piece : parsed.pieces) {
    if (!piece.is_placeholder) continue;
    if (!contains(placeholder_names(), piece.text)) {
      std::string message = "unknown placeholder '" + braced(piece.text) + "'";
      if (const auto guess = closest_match(piece.text, placeholder_names())) {
        message += " (did you mean '" + braced(*guess) + "'?)";
      } else {
        message += " (known: " + braced_list(placeholder_names()) + ")";
      }
      return message;
    }
    if (!contains(placeholders_allowed_in(field), piece.text)) {
      return "placeholder '" + braced(piece.text) + "' is not available in " + field_words(field) +
             " (available: " + braced_list(placeholders_allowed_in(field)) + ")";
    }
  }
  return std::nullopt;
}

bool uses_placeholder(std::string_view text, std::string_view name) {
  const Parsed parsed = parse(text);
  return std::any_of(parsed.pieces.begin(), parsed.pieces.end(),
                     [&](const Piece& p) { return p.is_placeholder && p.text == name; });
}

std::string expand(std::string_view text, const Placeholders& values) {
  const Parsed parsed = parse(text);
  if (parsed.error) {
    throw std::logic_error("template '" + std::string(text) + "': " + *parsed.error);
  }
  std::string out;
  for (const Piece& piece : parsed.pieces) {
    if (!piece.is_placeholder) {
      out += piece.text;
      continue;
    }
    const std::optional<std::string>* value = values.find(piece.text);
    if (value == nullptr || !value->has_value()) {
      throw std::logic_error("template '" + std::string(text) + "': no value for '" +
                             braced(piece.text) + "'");
    }
    out += **value;
  }
  return out;
}

std::vector<std::string> expand(const std::vector<std::string>& argv, const Placeholders& values) {
  std::vector<std::string> out;
  out.reserve(argv.size());
  for (const std::string& element : argv) out.push_back(expand(element, values));
  return out;
}

}  // namespace raygate
