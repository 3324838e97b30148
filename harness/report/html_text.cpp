// Text and image helpers of the HTML report: escaping, base64, data: URIs, badges.
#include <OpenImageIO/imagebuf.h>
#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <fstream>
#include <iterator>
#include <utility>

#include "core/fs.h"
#include "compare/image_file.h"
#include "core/sanitize.h"
#include "report/html_parts.h"

namespace raygate::report::html {
namespace {

constexpr std::array<std::pair<std::string_view, std::string_view>, 5> kBrowserImages{{
    {".png", "image/png"},
    {".jpg", "image/jpeg"},
    {".jpeg", "image/jpeg"},
    {".gif", "image/gif"},
    {".webp", "image/webp"},
}};

std::optional<std::string> read_bytes(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return std::nullopt;
  return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

std::string lower_extension(const std::filesystem::path& path) {
  std::string ext = path.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return ext;
}

// Browsers do not show PPM or EXR: convert through OpenImageIO (8 bits, as the evidence is).
std::optional<std::string> converted_png(const std::filesystem::path& path) {
  OIIO::ImageBuf image = current_image(path);
  if (!image.read(0, 0, true)) return std::nullopt;
  const TempDir temp("raygate-report");
  const std::filesystem::path png = temp.path() / "image.png";
  if (!image.write(png.string(), OIIO::TypeDesc::UINT8)) return std::nullopt;
  return read_bytes(png);
}

}  // namespace

std::string escape(std::string_view raw) {
  const std::string text = markup_text(raw);  // controls and bidi overrides shown, not obeyed
  std::string out;
  out.reserve(text.size());
  for (const char c : text) {
    switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      case '\'': out += "&#39;"; break;
      default: out += c;
    }
  }
  return out;
}

std::string base64(std::string_view bytes) {
  static constexpr char kAlphabet[] =
      "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  out.reserve((bytes.size() + 2) / 3 * 4);
  for (std::size_t i = 0; i < bytes.size(); i += 3) {
    const std::size_t n = std::min<std::size_t>(3, bytes.size() - i);
    std::uint32_t chunk = 0;
    for (std::size_t k = 0; k < 3; ++k) {
      const auto byte = k < n ? static_cast<unsigned char>(bytes[i + k]) : 0u;
      chunk = (chunk << 8) | byte;
    }
    for (std::size_t k = 0; k < 4; ++k) {
      out += k <= n ? kAlphabet[(chunk >> (18 - 6 * k)) & 0x3F] : '=';
    }
  }
  return out;
}

std::optional<std::string> image_data_uri(const std::filesystem::path& path) {
  std::error_code error;
  if (path.empty() || !std::filesystem::is_regular_file(path, error)) return std::nullopt;
  const std::string ext = lower_extension(path);
  for (const auto& [known, mime] : kBrowserImages) {
    if (ext != known) continue;
    const auto bytes = read_bytes(path);
    if (!bytes) return std::nullopt;
    return fmt::format("data:{};base64,{}", mime, base64(*bytes));
  }
  const auto png = converted_png(path);
  if (!png) return std::nullopt;
  return "data:image/png;base64," + base64(*png);
}

std::string outcome_class(GateOutcome outcome) {
  return fmt::format("gate-{}", to_string(outcome));
}

std::string badge(GateOutcome outcome) {
  std::string text(to_string(outcome));
  if (outcome == GateOutcome::unmeasured) text = "not measured";
  return fmt::format(R"(<span class="badge {}">{}</span>)", outcome_class(outcome), text);
}

std::string anchor(std::string_view scene_id) {
  std::string out = "scene-";
  for (const char c : scene_id) {
    out += std::isalnum(static_cast<unsigned char>(c)) ? c : '-';
  }
  return out;
}

}  // namespace raygate::report::html
