#include "cli/finite_numbers.h"

#include "core/number_text.h"
#include "core/utf8.h"

namespace raygate::cli {

void refuse_empty_and_non_finite_values(CLI::App& app) {
  // A check per option rather than one on the App: CLI11 names the option in the error it
  // throws for a failed check ("--max-minutes: ..."), and a value from raygate.toml or
  // RAYGATE_* passes the same checks when it becomes the option's default.
  const CLI::Validator finite(non_finite_problem, "", "FINITE");  // --help says "FLOAT in [..]"
  // `golden verify --golden-dir ''` checked the shipped goldens, which bless would overwrite.
  const CLI::Validator given(empty_value_problem, "", "");
  const CLI::Validator whole(whole_number_problem, "", "");
  for (CLI::Option* option : app.get_options()) {
    if (option->get_type_size() == 0) continue;                               // a flag
    option->check(given)->check(CLI::Validator(utf8_value_problem, "", ""));  // paths in JSON
    const std::string type = option->get_type_name();
    // "1e9" for a count: CLI11 said only "Could not convert".
    if (type.rfind("INT", 0) == 0 || type.rfind("UINT", 0) == 0) option->check(whole);
    if (type.rfind("FLOAT", 0) != 0) continue;
    option->check(finite);  // after any range check, which NaN passes and infinity fails
    option->check(CLI::Validator(padded_number_problem, "", ""));
  }
  for (CLI::App* command : app.get_subcommands([](CLI::App*) { return true; })) {
    refuse_empty_and_non_finite_values(*command);
  }
}

}  // namespace raygate::cli
