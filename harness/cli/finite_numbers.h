// Every value on raygate's command line is given and every number is finite. CLI11 reads a FLOAT
// with strtold, which takes "nan", "inf" and "1e999", and its Range check lets NaN pass (a NaN
// budget stopped a run after one round, passed it and stored null); an empty value quietly meant
// the option's default. One sweep over every option of every subcommand covers options added later.
#pragma once

#include <CLI/CLI.hpp>

namespace raygate::cli {

// Checks under `app` and its subcommands, however deep: each option's value is not empty and is
// UTF-8 text, and each FLOAT option's is finite; a usage error naming the option, exit 2.
void refuse_empty_and_non_finite_values(CLI::App& app);

}  // namespace raygate::cli
