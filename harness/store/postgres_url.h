// Team store locations (postgresql://USER[:PASSWORD]@HOST[:PORT]/DATABASE[?KEY=VALUE...]):
// checking one with libpq's own parser before connecting, and printing it without its password.
// A --store argument ends up in messages, CI logs and reports, so nothing raygate prints about
// a store may carry the password; the URL as typed is used only to connect.
#pragma once

#include <string>
#include <vector>

namespace raygate {

// "postgresql://" or "postgres://".
bool is_postgresql_url(const std::string& location);

// The URL with the password taken out of the user part and any password=... query parameter
// dropped: "postgresql://ci:s3cret@db:5432/raygate" -> "postgresql://ci@db:5432/raygate".
// Works on any SCHEME://USER:PASSWORD@... URL; never throws; text without "://" (a path) comes
// back unchanged.
std::string redact_postgresql_url(const std::string& url);

struct PostgresUrl {
  std::string url;                   // as given: what libpq connects with
  std::string redacted;              // for every message and location()
  std::vector<std::string> secrets;  // the password as written and as decoded, to scrub
};

// Checks the URL with libpq's parser: a malformed one is a UsageError naming the redacted URL
// and the expected form.
PostgresUrl parse_postgresql_url(const std::string& url);

// `text` with every secret of `url` replaced by "***" (libpq may echo parts of a URL).
std::string scrub_secrets(std::string text, const PostgresUrl& url);

}  // namespace raygate
