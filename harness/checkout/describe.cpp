#include "checkout/describe.h"

#include <fmt/format.h>

#include <cctype>
#include <ctime>
#include <string_view>

#include "core/utf8.h"

namespace raygate::git {
namespace {

// Whether an encoding header names ISO-8859-1 in one of the spellings git and iconv accept
// ("ISO-8859-1", "iso8859-1", "latin1", "L1", "CP819", ...).
bool names_latin1(std::string_view encoding) {
  std::string key;
  for (const char c : encoding) {
    if (c == '-' || c == '_' || c == ' ') continue;
    key.push_back(static_cast<char>(std::tolower(static_cast<unsigned char>(c))));
  }
  for (const std::string_view alias : {"iso88591", "latin1", "l1", "cp819", "ibm819"}) {
    if (key == alias) return true;
  }
  return false;
}

std::string first_line(const char* message) {
  if (message == nullptr) return {};
  std::string_view text(message);
  const auto end = text.find_first_of("\r\n");
  return std::string(text.substr(0, end));
}

std::string short_id(git_commit* commit) {
  Buf buf;
  check(git_object_short_id(buf.out(), reinterpret_cast<const git_object*>(commit)),
        "abbreviating commit " + to_hex(*git_commit_id(commit)));
  return buf.str();
}

}  // namespace

std::string iso8601(std::int64_t seconds, int offset_minutes) {
  // Shift to local wall time first, then print it as if it were UTC with the offset attached.
  const std::time_t local = static_cast<std::time_t>(seconds + std::int64_t{offset_minutes} * 60);
  std::tm parts{};
  gmtime_r(&local, &parts);
  const char sign = offset_minutes < 0 ? '-' : '+';
  const int magnitude = offset_minutes < 0 ? -offset_minutes : offset_minutes;
  return fmt::format("{:04}-{:02}-{:02}T{:02}:{:02}:{:02}{}{:02}:{:02}", parts.tm_year + 1900,
                     parts.tm_mon + 1, parts.tm_mday, parts.tm_hour, parts.tm_min, parts.tm_sec,
                     sign, magnitude / 60, magnitude % 60);
}

std::string commit_text(git_commit* commit, std::string_view bytes) {
  const char* encoding = git_commit_message_encoding(commit);
  if (encoding != nullptr && names_latin1(encoding)) return latin1_to_utf8(bytes);
  return repaired_utf8(bytes);
}

Revision describe_commit(git_commit* commit, std::string revision, std::string ref_name) {
  Revision out;
  // Named by the user or by a ref, and refs are bytes in git: repaired like the rest.
  out.revision = repaired_utf8(revision);
  out.ref_name = repaired_utf8(ref_name);
  out.sha = to_hex(*git_commit_id(commit));
  out.short_sha = short_id(commit);
  out.subject = commit_text(commit, first_line(git_commit_summary(commit)));
  const git_signature* author = git_commit_author(commit);
  const bool named = author != nullptr && author->name != nullptr;
  out.author = named ? commit_text(commit, author->name) : "";
  out.commit_time = iso8601(git_commit_time(commit), git_commit_time_offset(commit));
  return out;
}

}  // namespace raygate::git
