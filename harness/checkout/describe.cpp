#include "checkout/describe.h"

#include <fmt/format.h>

#include <ctime>
#include <string_view>

namespace raygate::git {
namespace {

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

Revision describe_commit(git_commit* commit, std::string revision, std::string ref_name) {
  Revision out;
  out.revision = std::move(revision);
  out.ref_name = std::move(ref_name);
  out.sha = to_hex(*git_commit_id(commit));
  out.short_sha = short_id(commit);
  out.subject = first_line(git_commit_summary(commit));
  const git_signature* author = git_commit_author(commit);
  out.author = author != nullptr && author->name != nullptr ? author->name : "";
  out.commit_time = iso8601(git_commit_time(commit), git_commit_time_offset(commit));
  return out;
}

}  // namespace raygate::git
