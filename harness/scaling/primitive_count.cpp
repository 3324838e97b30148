// A stream buffer that looks only at the first word of each line, so counting a 600k-sphere
// scene costs its generation and nothing more.
#include "scaling/primitive_count.h"

#include <ostream>
#include <streambuf>

#include "spd.h"

namespace raygate {
namespace {

class PrimitiveCounter : public std::streambuf {
 public:
  std::int64_t count() const { return count_; }

 protected:
  int_type overflow(int_type ch) override {
    if (ch == traits_type::eof()) return traits_type::not_eof(ch);
    const char c = traits_type::to_char_type(ch);
    if (c == '\n') {
      finish_word();
      at_line_start_ = true;
      word_.clear();
    } else if (at_line_start_) {
      if (c == ' ' || c == '\t') {
        finish_word();
      } else if (word_.size() < 3) {
        word_.push_back(c);
      } else {
        at_line_start_ = false;  // longer than any primitive keyword
      }
    }
    return ch;
  }

 private:
  void finish_word() {
    if (at_line_start_ && (word_ == "s" || word_ == "c" || word_ == "p" || word_ == "pp")) ++count_;
    at_line_start_ = false;
  }

  std::string word_;
  bool at_line_start_ = true;
  std::int64_t count_ = 0;
};

}  // namespace

std::int64_t count_primitives(const std::string& scene, int size) {
  PrimitiveCounter counter;
  std::ostream out(&counter);
  scenes::GenerateOptions options;
  options.size = size;
  scenes::generate(scene, options, out);
  out.flush();
  return counter.count();
}

}  // namespace raygate

namespace raygate {

std::int64_t CachedPrimitiveCount::operator()(const std::string& scene, int size) {
  const auto key = std::make_pair(scene, size);
  if (const auto found = counts_.find(key); found != counts_.end()) return found->second;
  const std::int64_t n = count_primitives(scene, size);
  counts_.emplace(key, n);
  return n;
}

}  // namespace raygate
