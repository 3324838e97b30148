// Parsing and redacting team store URLs.
#include "store/postgres_url.h"

#include <fmt/core.h>
#include <libpq-fe.h>

#include <algorithm>
#include <cctype>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "core/error.h"

namespace raygate {

namespace {

constexpr const char* kUrlForm = "postgresql://USER[:PASSWORD]@HOST[:PORT]/DATABASE";

int hex_digit(char c) {
  if (c >= '0' && c <= '9') return c - '0';
  if (c >= 'a' && c <= 'f') return c - 'a' + 10;
  if (c >= 'A' && c <= 'F') return c - 'A' + 10;
  return -1;
}

// "%70assword" -> "password"; a malformed escape is kept as it is.
std::string percent_decoded(const std::string& text) {
  std::string out;
  for (std::size_t i = 0; i < text.size(); ++i) {
    if (text[i] == '%' && i + 2 < text.size()) {
      const int high = hex_digit(text[i + 1]);
      const int low = hex_digit(text[i + 2]);
      if (high >= 0 && low >= 0) {
        out += static_cast<char>(high * 16 + low);
        i += 2;
        continue;
      }
    }
    out += text[i];
  }
  return out;
}

// The query with every password=... parameter dropped ("" when none is left); `dropped` gets
// their values.
std::string query_without_password(const std::string& query, std::vector<std::string>& dropped) {
  std::string kept;
  std::size_t start = 0;
  while (start <= query.size()) {
    std::size_t end = query.find('&', start);
    if (end == std::string::npos) end = query.size();
    const std::string parameter = query.substr(start, end - start);
    const std::size_t equals = parameter.find('=');
    if (percent_decoded(parameter.substr(0, equals)) == "password") {
      if (equals != std::string::npos) dropped.push_back(parameter.substr(equals + 1));
    } else if (!parameter.empty()) {
      kept += (kept.empty() ? "" : "&") + parameter;
    }
    start = end + 1;
  }
  return kept;
}

// Where the user part ends for redaction: the last '@' before the query. Wider than libpq's
// reading (USER[:PASSWORD] up to an '@' before any '/') on purpose: a password holding an
// unencoded '/' or '@' is not a valid URL to libpq, and must still not be printed in the error
// that says so.
std::size_t redacted_user_part_end(const std::string& rest) {
  const std::size_t question = rest.find('?');
  const std::size_t at =
      question == std::string::npos ? rest.rfind('@') : rest.rfind('@', question);
  return at;
}

// The redacted URL, and the secrets as written in it.
std::string redact(const std::string& url, std::vector<std::string>& secrets) {
  const std::size_t scheme = url.find("://");
  if (scheme == std::string::npos) return url;
  std::string rest = url.substr(scheme + 3);
  std::size_t host = 0;  // where the host starts in `rest`
  const std::size_t at = redacted_user_part_end(rest);
  if (at != std::string::npos) {
    host = at;
    const std::size_t colon = rest.find(':');
    if (colon < at) {
      const std::string password = rest.substr(colon + 1, at - colon - 1);
      secrets.push_back(password);
      // libpq reads an unencoded '@' or '/' as the end of the user part and echoes the rest as
      // a host name: the tails after them are secrets too (all but the very short ones, which
      // would blank out ordinary words of the message).
      for (std::size_t cut = password.find_first_of("@/"); cut != std::string::npos;
           cut = password.find_first_of("@/", cut + 1)) {
        if (password.size() - cut - 1 >= 3) secrets.push_back(password.substr(cut + 1));
      }
      rest.erase(colon, at - colon);
      host = colon;
    }
  }
  const std::size_t question = rest.find('?', host);
  if (question != std::string::npos) {
    const std::string query = query_without_password(rest.substr(question + 1), secrets);
    rest = rest.substr(0, question) + (query.empty() ? "" : "?" + query);
  }
  return url.substr(0, scheme + 3) + rest;
}

// libpq checks ports only when it connects, and calls a bad one a connection failure: a port
// that is not a number (one per host, comma-separated) is the URL's fault. Returns the problem.
std::string port_problem(PQconninfoOption* options) {
  for (PQconninfoOption* option = options; option && option->keyword; ++option) {
    if (std::string(option->keyword) != "port" || !option->val) continue;
    const std::string ports = option->val;
    std::size_t start = 0;
    while (start <= ports.size()) {
      std::size_t end = ports.find(',', start);
      if (end == std::string::npos) end = ports.size();
      const std::string port = ports.substr(start, end - start);
      const bool digits = !port.empty() && port.size() <= 5 &&
                          std::all_of(port.begin(), port.end(),
                                      [](unsigned char c) { return std::isdigit(c) != 0; });
      if (!port.empty() && (!digits || std::stoi(port) < 1 || std::stoi(port) > 65535)) {
        return "port \"" + port + "\" is not a number from 1 to 65535";
      }
      start = end + 1;
    }
  }
  return {};
}

// At most 80 characters of what the user wrote, so a pasted blob does not flood the message.
std::string clipped(const std::string& text) {
  return text.size() > 80 ? text.substr(0, 80) + "..." : text;
}

// Likewise the settings libpq takes from a fixed list of words, which it checks only when it
// connects ("invalid sslmode value"), and the numbers it reads then: the URL's fault, said before
// anything is opened. Returns the problem.
std::string setting_problem(PQconninfoOption* options) {
  static const std::map<std::string, std::vector<std::string>> kWords{
      {"sslmode", {"disable", "allow", "prefer", "require", "verify-ca", "verify-full"}},
      {"gssencmode", {"disable", "prefer", "require"}},
      {"channel_binding", {"disable", "prefer", "require"}},
      {"target_session_attrs",
       {"any", "read-write", "read-only", "primary", "standby", "prefer-standby"}},
      {"load_balance_hosts", {"disable", "random"}}};
  for (PQconninfoOption* option = options; option && option->keyword; ++option) {
    if (!option->val) continue;
    const std::string keyword = option->keyword;
    const std::string value = option->val;
    if (const auto words = kWords.find(keyword); words != kWords.end()) {
      if (std::find(words->second.begin(), words->second.end(), value) != words->second.end()) {
        continue;
      }
      std::string list;
      for (const std::string& word : words->second) list += (list.empty() ? "" : ", ") + word;
      return fmt::format("{} \"{}\" is not one of {}", keyword, clipped(value), list);
    }
    const bool number = keyword == "connect_timeout" || keyword.starts_with("keepalives");
    if (number && (value.empty() || value.size() > 9 ||
                   !std::all_of(value.begin(), value.end(),
                                [](unsigned char c) { return std::isdigit(c) != 0; }))) {
      return fmt::format("{} \"{}\" is not a whole number of seconds", keyword, clipped(value));
    }
  }
  return {};
}

// The password libpq decoded from the URL ("" when none or when the URL does not parse).
std::string parsed_password(PQconninfoOption* options) {
  for (PQconninfoOption* option = options; option && option->keyword; ++option) {
    if (std::string(option->keyword) == "password" && option->val) return option->val;
  }
  return {};
}

// No empty secret (it would match everywhere); longest first, so a decoded password inside its
// written form cannot leave a piece behind.
void tidy(std::vector<std::string>& secrets) {
  std::erase(secrets, std::string());
  std::sort(secrets.begin(), secrets.end(),
            [](const std::string& a, const std::string& b) { return a.size() > b.size(); });
}

}  // namespace

bool is_postgresql_url(const std::string& location) {
  return location.starts_with("postgresql://") || location.starts_with("postgres://");
}

std::string redact_postgresql_url(const std::string& url) {
  std::vector<std::string> secrets;
  return redact(url, secrets);
}

PostgresUrl parse_postgresql_url(const std::string& url) {
  PostgresUrl parsed;
  parsed.url = url;
  std::vector<std::string> written;
  parsed.redacted = redact(url, written);
  for (const std::string& secret : written) {
    parsed.secrets.push_back(secret);
    parsed.secrets.push_back(percent_decoded(secret));
  }
  tidy(parsed.secrets);
  char* error = nullptr;
  const std::unique_ptr<PQconninfoOption, decltype(&PQconninfoFree)> options(
      PQconninfoParse(url.c_str(), &error), &PQconninfoFree);
  std::string problem = options ? port_problem(options.get()) : std::string(error ? error : "");
  if (options && problem.empty()) problem = setting_problem(options.get());
  PQfreemem(error);
  while (!problem.empty() && (problem.back() == '\n' || problem.back() == ' ')) problem.pop_back();
  if (!options || !problem.empty()) {
    throw UsageError(fmt::format("--store {}: not a valid PostgreSQL URL ({}); the form is {}",
                                 parsed.redacted, scrub_secrets(problem, parsed), kUrlForm));
  }
  const std::string password = parsed_password(options.get());
  if (!password.empty()) parsed.secrets.push_back(password);
  tidy(parsed.secrets);
  return parsed;
}

std::string scrub_secrets(std::string text, const PostgresUrl& url) {
  if (!url.url.empty()) {
    for (std::size_t at = text.find(url.url); at != std::string::npos;
         at = text.find(url.url, at + url.redacted.size())) {
      text.replace(at, url.url.size(), url.redacted);
    }
  }
  for (const std::string& secret : url.secrets) {
    if (secret.empty()) continue;
    for (std::size_t at = text.find(secret); at != std::string::npos;
         at = text.find(secret, at + 3)) {
      text.replace(at, secret.size(), "***");
    }
  }
  return text;
}

}  // namespace raygate
