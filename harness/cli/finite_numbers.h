// Every number on raygate's command line is a finite one. CLI11 reads a FLOAT option with strtold,
// which takes "nan", "inf" and "1e999" (inf); its Range check compares with < and >, which NaN
// passes. A NaN budget then stopped a run after one round, passed it and stored null. One sweep
// over every option of every subcommand, so an option added later is covered without a word.
#pragma once

#include <CLI/CLI.hpp>

namespace raygate::cli {

// Adds to each FLOAT option under `app` (itself and its subcommands, however deep) a check
// that refuses a value that is not a finite number: a usage error naming the option, exit 2.
void refuse_non_finite_numbers(CLI::App& app);

}  // namespace raygate::cli
