// Parameter lists of the dialect layer.
#include "store/sql_database.h"

namespace raygate {

SqlParams& SqlParams::text(const std::string& value) {
  values_.emplace_back(value);
  return *this;
}

SqlParams& SqlParams::integer(std::optional<std::int64_t> value) {
  if (value) {
    values_.emplace_back(*value);
  } else {
    values_.emplace_back(std::monostate{});
  }
  return *this;
}

SqlParams& SqlParams::flag(bool value) {
  values_.emplace_back(value);
  return *this;
}

SqlParams& SqlParams::real(std::optional<double> value) {
  if (value) {
    values_.emplace_back(*value);
  } else {
    values_.emplace_back(std::monostate{});
  }
  return *this;
}

}  // namespace raygate
